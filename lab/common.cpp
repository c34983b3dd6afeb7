#include "verbs.hpp"

#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace pl::lab {

int report(const Error& e) {
    std::fputs(e.format().c_str(), stderr);
    return static_cast<int>(e.code);
}

void exit_after_hang(int code) {
    std::fflush(stdout);
    std::fflush(stderr);
    std::_Exit(code);
}

std::string cache_dir(const CommonOptions& c) {
    if (c.no_cache) return {};
    if (const char* x = std::getenv("PASSLAB_CACHE_DIR")) return x;
    std::filesystem::path base;
    if (const char* x = std::getenv("XDG_CACHE_HOME")) base = x;
    else if (const char* h = std::getenv("HOME")) base = std::filesystem::path(h) / ".cache";
    else return {};
    return (base / "passlab" / "spirv").string();
}

Result<std::optional<std::array<int, 2>>> parse_size(const std::string& s) {
    if (s.empty()) return std::optional<std::array<int, 2>>{};
    int w = 0, h = 0;
    char x = 0, extra = 0;
    if (std::sscanf(s.c_str(), "%d%c%d%c", &w, &x, &h, &extra) != 3 || (x != 'x' && x != 'X')) {
        Error e = make_error("--size expects WxH (e.g. 640x360), got '" + s + "'");
        e.code = ExitCode::usage;
        return e;
    }
    // The same bound the graph validator uses for images: refuse before allocating anything.
    if (w < 1 || h < 1 || w > 16384 || h > 16384) {
        Error e = make_error("--size " + s + " is outside 1x1 .. 16384x16384");
        e.code = ExitCode::usage;
        return e;
    }
    return std::optional<std::array<int, 2>>{std::array<int, 2>{w, h}};
}

Result<LoadedPreset> resolve_and_configure(const std::string& preset, const std::string& size,
                                           const std::vector<std::string>& set, const CommonOptions& c) {
    auto parsed = parse_size(size);
    if (!parsed) return parsed.error();
    auto toml = exec::resolve_preset(preset);
    if (!toml) return toml.error();
    LoadedPreset lp;
    lp.toml = *toml;
    lp.options.size = *parsed;
    lp.options.set = set;
    lp.options.cache_dir = cache_dir(c);
    return lp;
}

} // namespace pl::lab
