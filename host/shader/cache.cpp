// Files <dir>/<fnv1a64 of key>.spv holding all stages of a program. The key text contains every
// expanded source (includes, preamble, defines), so any change to any input misses. Cache
// problems are never errors: the compile simply happens.
#include "shader/cache.hpp"

#include <fstream>

#include <unistd.h>

namespace fs = std::filesystem;

namespace pl::shader {

namespace {

uint64_t fnv1a(const std::string& s) {
    uint64_t h = 1469598103934665603ull;
    for (unsigned char c : s) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

fs::path entry(const fs::path& dir, const std::string& key) {
    char name[32];
    std::snprintf(name, sizeof name, "%016llx.spv", static_cast<unsigned long long>(fnv1a(key)));
    return dir / name;
}

constexpr uint32_t kMagic = 0x504c5356;  // "PLSV"

} // namespace

std::optional<std::vector<StageSpirv>> cache_load(const fs::path& dir, const std::string& key) {
    std::ifstream in(entry(dir, key), std::ios::binary);
    if (!in) return std::nullopt;
    auto read32 = [&](uint32_t& v) { return static_cast<bool>(in.read(reinterpret_cast<char*>(&v), 4)); };
    uint32_t magic = 0, count = 0, key_size = 0;
    if (!read32(magic) || magic != kMagic || !read32(key_size) || key_size != key.size()) return std::nullopt;
    // The full key is stored too, so a 64-bit hash collision can never return wrong code.
    std::string stored(key_size, '\0');
    if (!in.read(stored.data(), key_size) || stored != key) return std::nullopt;
    if (!read32(count) || count > 6) return std::nullopt;
    std::vector<StageSpirv> out;
    for (uint32_t i = 0; i < count; ++i) {
        uint32_t stage = 0, n = 0;
        if (!read32(stage) || !read32(n) || stage > 5 || n > (64u << 20)) return std::nullopt;
        StageSpirv s{static_cast<Stage>(stage), std::vector<uint32_t>(n)};
        if (!in.read(reinterpret_cast<char*>(s.words.data()), static_cast<std::streamsize>(n) * 4)) return std::nullopt;
        out.push_back(std::move(s));
    }
    return out;
}

void cache_store(const fs::path& dir, const std::string& key, const std::vector<StageSpirv>& stages) {
    std::error_code ec;
    fs::create_directories(dir, ec);
    if (ec) return;
    fs::path final_path = entry(dir, key);
    fs::path tmp = final_path;
    tmp += ".tmp" + std::to_string(::getpid());
    {
        std::ofstream out(tmp, std::ios::binary);
        if (!out) return;
        auto write32 = [&](uint32_t v) { out.write(reinterpret_cast<const char*>(&v), 4); };
        write32(kMagic);
        write32(static_cast<uint32_t>(key.size()));
        out.write(key.data(), static_cast<std::streamsize>(key.size()));
        write32(static_cast<uint32_t>(stages.size()));
        for (const auto& s : stages) {
            write32(static_cast<uint32_t>(s.stage));
            write32(static_cast<uint32_t>(s.words.size()));
            out.write(reinterpret_cast<const char*>(s.words.data()), static_cast<std::streamsize>(s.words.size() * 4));
        }
        if (!out) {
            fs::remove(tmp, ec);
            return;
        }
    }
    fs::rename(tmp, final_path, ec);  // atomic: readers see the old file or the whole new one
    if (ec) fs::remove(tmp, ec);
}

} // namespace pl::shader
