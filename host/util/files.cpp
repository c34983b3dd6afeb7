#include "util/files.hpp"

#include <fstream>

namespace fs = std::filesystem;

namespace pl {

Result<std::uintmax_t> check_regular_file(const fs::path& file, std::uintmax_t max_bytes, const std::string& what) {
    std::error_code ec;
    auto st = fs::status(file, ec);
    if (ec || !fs::exists(st)) {
        Error e = make_error("no such " + what + " file '" + file.string() + "'" +
                             (ec && ec != std::errc::no_such_file_or_directory ? " (" + ec.message() + ")" : ""));
        return e;
    }
    if (!fs::is_regular_file(st)) {
        const char* kind = fs::is_directory(st) ? "a folder" : fs::is_fifo(st) ? "a FIFO" :
                           fs::is_character_file(st) || fs::is_block_file(st) ? "a device" : "not a regular file";
        return make_error(what + " file '" + file.string() + "' is " + kind + ": only regular files are read");
    }
    std::uintmax_t size = fs::file_size(file, ec);
    if (ec) {
        Error e = make_error("cannot read " + what + " file '" + file.string() + "': " + ec.message());
        e.code = ExitCode::environment;
        return e;
    }
    if (size > max_bytes)
        return make_error(what + " file '" + file.string() + "' is " + std::to_string(size >> 20) +
                          " MiB, more than the " + std::to_string(max_bytes >> 20) + " MiB a " + what + " file may have");
    return size;
}

Result<std::string> read_file_capped(const fs::path& file, std::uintmax_t max_bytes, const std::string& what) {
    auto size = check_regular_file(file, max_bytes, what);
    if (!size) return size.error();
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        Error e = make_error("cannot read " + what + " file '" + file.string() + "'");
        e.code = ExitCode::environment;
        return e;
    }
    std::string s(static_cast<size_t>(*size), '\0');
    in.read(s.data(), static_cast<std::streamsize>(s.size()));
    s.resize(static_cast<size_t>(in.gcount()));
    return s;
}

std::vector<fs::path> files_under(const fs::path& dir, size_t max_entries, bool* truncated) {
    std::vector<fs::path> out;
    if (truncated) *truncated = false;
    std::error_code ec;
    size_t visited = 0;
    for (fs::recursive_directory_iterator it(dir, fs::directory_options::skip_permission_denied, ec), end;
         !ec && it != end; it.increment(ec)) {
        if (++visited > max_entries) {
            if (truncated) *truncated = true;
            break;
        }
        std::error_code st;
        if (it->is_regular_file(st) && !st) out.push_back(it->path());
    }
    return out;
}

} // namespace pl
