#include "verbs.hpp"

#include "util/files.hpp"
#include "util/paths.hpp"
#include "util/scan.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <set>

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

std::chrono::milliseconds timeout(const CommonOptions& c) {
    return std::chrono::milliseconds(static_cast<long long>(c.timeout_s * 1000));
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
    // Checked digits (sscanf's %d wrapped 4294967297 to 1): a number too large for any type
    // becomes one the range check below refuses.
    auto dim = [](std::string_view d) -> std::optional<unsigned long long> {
        if (d.empty() || !std::all_of(d.begin(), d.end(), [](char c) { return c >= '0' && c <= '9'; })) return std::nullopt;
        return scan::parse_decimal(d, 1ull << 40).value_or(1ull << 40);
    };
    size_t x = s.find_first_of("xX");
    auto w = x == std::string::npos ? std::nullopt : dim(std::string_view(s).substr(0, x));
    auto h = x == std::string::npos ? std::nullopt : dim(std::string_view(s).substr(x + 1));
    if (!w || !h) {
        Error e = make_error("--size expects WxH (e.g. 640x360), got '" + s + "'");
        e.code = ExitCode::usage;
        return e;
    }
    // The same bound the graph validator uses for images: refuse before allocating anything.
    if (*w < 1 || *h < 1 || *w > 16384 || *h > 16384) {
        Error e = make_error("--size " + s + " is outside 1x1 .. 16384x16384");
        e.code = ExitCode::usage;
        return e;
    }
    return std::optional<std::array<int, 2>>{std::array<int, 2>{static_cast<int>(*w), static_cast<int>(*h)}};
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
    if (fs::is_directory(arg, ec) && !fs::exists(fs::path(arg) / "preset.toml", ec)) {
        for (const auto& f : files_under(arg))
            if (f.filename() == "preset.toml") out.push_back(canonical_or_normal(f));
        std::sort(out.begin(), out.end());
        if (out.empty()) return make_error("no preset.toml under '" + arg + "'");
        return out;
    }
    auto p = exec::resolve_preset(arg);
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
    return std::vector<std::filesystem::path>{canonical_or_normal(c.exercise)};
}

void describe_exercise(const CommonOptions& c, const exec::CompiledGraph& g) {
    if (c.exercise.empty()) return;
    namespace fs = std::filesystem;
    const fs::path dir = canonical_or_normal(c.exercise);
    std::set<fs::path> read;  // every file the build read, canonical once
    for (const auto& d : g.dependencies) read.insert(canonical_or_normal(d));
    bool truncated = false;
    for (const auto& file : files_under(dir, 20000, &truncated)) {
        const fs::path f = canonical_or_normal(file);
        bool used = read.count(f) > 0;
        const std::string rel = f.lexically_relative(dir).string();
        if (used) std::fprintf(stderr, "exercise: using your %s\n", rel.c_str());
        else if (f.extension() != ".md" && f.extension() != ".txt")
            std::fprintf(stderr, "exercise: warning: %s shadows no file the preset reads (is the name right?)\n", rel.c_str());
    }
    if (truncated)
        std::fprintf(stderr, "exercise: warning: %s holds more than 20000 entries; only the first were listed (is it the right folder?)\n",
                     c.exercise.c_str());
}

} // namespace pl::lab
