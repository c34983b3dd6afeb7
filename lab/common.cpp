#include "verbs.hpp"
#include "sources.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>

namespace pl::lab {

int report(const Error& e) {
    std::fputs(map_scratch_error(e).format().c_str(), stderr);
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
    auto toml = resolve_source(preset);
    if (!toml) return toml.error();
    LoadedPreset lp;
    lp.toml = *toml;
    lp.options.size = *parsed;
    lp.options.set = set;
    lp.options.cache_dir = cache_dir(c);
    auto overlay = exercise_overlay(c);
    if (!overlay) return overlay.error();
    lp.options.overlay_dirs = *overlay;
    return lp;
}

// Every preset.toml under `arg` (a preset folder, a .toml, a name, or a tree of presets).
Result<std::vector<std::filesystem::path>> collect_presets(const std::string& arg) {
    namespace fs = std::filesystem;
    std::error_code ec;
    std::vector<fs::path> out;
    if (fs::is_directory(arg, ec) && !fs::exists(fs::path(arg) / "preset.toml", ec) && !import::detect_source(arg)) {
        for (const auto& e : fs::recursive_directory_iterator(arg, ec))
            if (e.path().filename() == "preset.toml") out.push_back(fs::absolute(e.path()));
        std::sort(out.begin(), out.end());
        if (out.empty()) return make_error("no preset.toml under '" + arg + "'");
        return out;
    }
    auto p = resolve_source(arg);  // a preset, or a Shadertoy/ISF source imported into a scratch folder
    if (!p) return p.error();
    out.push_back(*p);
    return out;
}

Result<std::vector<std::filesystem::path>> exercise_overlay(const CommonOptions& c) {
    if (c.exercise.empty()) return std::vector<std::filesystem::path>{};
    std::error_code ec;
    if (!std::filesystem::is_directory(c.exercise, ec)) {
        Error e = make_error("--exercise " + c.exercise + ": no such folder");
        e.code = ExitCode::usage;
        return e;
    }
    return std::vector<std::filesystem::path>{std::filesystem::absolute(c.exercise)};
}

void describe_exercise(const CommonOptions& c, const exec::CompiledGraph& g) {
    if (c.exercise.empty()) return;
    namespace fs = std::filesystem;
    const fs::path dir = fs::weakly_canonical(fs::absolute(c.exercise));
    std::set<fs::path> read;  // every file the build read, canonical once
    for (const auto& d : g.dependencies) read.insert(fs::weakly_canonical(d));
    std::error_code ec;
    for (auto it = fs::recursive_directory_iterator(dir, ec); !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
        if (!it->is_regular_file()) continue;
        const fs::path f = fs::weakly_canonical(it->path());
        bool used = read.count(f) > 0;
        const std::string rel = f.lexically_relative(dir).string();
        if (used) std::fprintf(stderr, "exercise: using your %s\n", rel.c_str());
        else if (f.extension() != ".md" && f.extension() != ".txt")
            std::fprintf(stderr, "exercise: warning: %s shadows no file the preset reads (is the name right?)\n", rel.c_str());
    }
}

} // namespace pl::lab
