#include "image/exr_header.hpp"

#include <cstdint>
#include <fstream>
#include <string>

namespace fs = std::filesystem;

namespace pl::image {

namespace {

constexpr unsigned char kMagic[4] = {0x76, 0x2f, 0x31, 0x01};
constexpr uint32_t kMultiPartBit = 0x1000;  // version field flags (OpenEXR file layout)

// A NUL-terminated name of at most 255 characters; false at end of file or when longer.
bool read_name(std::ifstream& in, std::string& out) {
    out.clear();
    for (int c; (c = in.get()) != EOF;) {
        if (c == 0) return true;
        if (out.size() == 255) return false;
        out += static_cast<char>(c);
    }
    return false;
}

} // namespace

Status check_exr_header(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    unsigned char head[8];
    const bool magic = in.read(reinterpret_cast<char*>(head), 4) && head[0] == kMagic[0] && head[1] == kMagic[1] &&
                       head[2] == kMagic[2] && head[3] == kMagic[3];
    if (!magic) return ok_status();  // not an EXR file: OpenImageIO's reader for it decides
    std::error_code ec;
    const auto file_size = fs::file_size(file, ec);
    if (ec) return make_error("cannot read image '" + file.string() + "': " + ec.message());
    if (!in.read(reinterpret_cast<char*>(head + 4), 4)) return make_error("'" + file.string() + "': an EXR file shorter than its header");
    const uint32_t version = head[4] | (head[5] << 8) | (head[6] << 16) | (static_cast<uint32_t>(head[7]) << 24);
    const bool multi_part = (version & kMultiPartBit) != 0;
    auto damaged = [&](const std::string& why) {
        return make_error("'" + file.string() + "': damaged EXR header: " + why);
    };
    // Each part's header is a list of attributes ended by an empty name; a multi-part file ends
    // its list of headers with one more empty name.
    for (int part = 0;; ++part) {
        std::string name, type;
        int attributes = 0;
        for (;; ++attributes) {
            if (!read_name(in, name)) return damaged("an attribute name is unterminated or longer than 255 characters");
            if (name.empty()) break;
            if (!read_name(in, type)) return damaged("attribute '" + name + "' has an unterminated type name");
            unsigned char s[4];
            if (!in.read(reinterpret_cast<char*>(s), 4)) return damaged("attribute '" + name + "' ends before its size");
            const int32_t size = static_cast<int32_t>(s[0] | (s[1] << 8) | (s[2] << 16) | (static_cast<uint32_t>(s[3]) << 24));
            const auto at = static_cast<std::uintmax_t>(in.tellg());
            if (size < 0 || static_cast<std::uintmax_t>(size) > file_size - at)
                return damaged("attribute '" + name + "' (" + type + ") claims " + std::to_string(size) + " bytes, " +
                               std::to_string(file_size - at) + " are left in the file");
            in.seekg(size, std::ios::cur);
        }
        if (!multi_part) return ok_status();
        if (attributes == 0) return part > 0 ? ok_status() : damaged("a multi-part file without a part");
    }
}

} // namespace pl::image
