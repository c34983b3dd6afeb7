#include "verbs.hpp"
#include "sources.hpp"

#include "util/files.hpp"
#include "util/paths.hpp"
#include "util/scan.hpp"

#include <algorithm>
#include <cstdio>
#include <cerrno>
#include <cstdlib>
#include <cstring>
#include <unistd.h>
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
        for (const auto& f : files_under(arg))
            if (f.filename() == "preset.toml") out.push_back(canonical_or_normal(f));
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
    return std::vector<std::filesystem::path>{canonical_or_normal(c.exercise)};
}

int describe_exercise(const CommonOptions& c, const exec::CompiledGraph& g) {
    if (c.exercise.empty()) return 0;
    namespace fs = std::filesystem;
    const fs::path dir = canonical_or_normal(c.exercise);
    std::set<fs::path> read;  // every file the build read, canonical once
    for (const auto& d : g.dependencies) read.insert(canonical_or_normal(d));
    int used_count = 0;
    bool truncated = false;
    for (const auto& file : files_under(dir, 20000, &truncated)) {
        const fs::path f = canonical_or_normal(file);
        bool used = read.count(f) > 0;
        used_count += used;
        const std::string rel = f.lexically_relative(dir).string();
        if (used) std::fprintf(stderr, "exercise: using your %s\n", rel.c_str());
        else if (f.extension() != ".md" && f.extension() != ".txt")
            std::fprintf(stderr, "exercise: warning: %s shadows no file the preset reads (is the name right?)\n", rel.c_str());
    }
    if (truncated)
        std::fprintf(stderr, "exercise: warning: %s holds more than 20000 entries; only the first were listed (is it the right folder?)\n",
                     c.exercise.c_str());
    return used_count;
}

std::vector<std::string> exercise_files(const std::filesystem::path& preset_toml, const exec::CompiledGraph& g) {
    namespace fs = std::filesystem;
    const fs::path root = preset_toml.parent_path();
    std::vector<std::string> out;
    std::error_code ec;
    // The preset's own exercise/ says which files a student rewrites.
    if (fs::is_directory(root / "exercise", ec)) {
        for (const auto& f : files_under(root / "exercise"))
            if (f.extension() != ".md" && f.extension() != ".txt")
                out.push_back(f.lexically_relative(root / "exercise").string());
    } else {
        // Otherwise any file of the preset's folder the build read, but the TOML itself.
        const fs::path canon_root = canonical_or_normal(root);
        for (const auto& d : g.dependencies) {
            fs::path f = canonical_or_normal(d);
            fs::path rel = f.lexically_relative(canon_root);
            if (!rel.empty() && *rel.begin() != ".." && f.filename() != "preset.toml") out.push_back(rel.string());
        }
    }
    std::sort(out.begin(), out.end());
    out.erase(std::unique(out.begin(), out.end()), out.end());
    return out;
}

namespace {

// `shown` is how the message names the output ("--junit out/r.xml").
Status check_writable_dir(const std::string& dir, const std::string& shown) {
    namespace fs = std::filesystem;
    auto fail = [&](const std::string& why) {
        Error e = make_error(shown + ": " + why);
        e.code = ExitCode::environment;
        return e;
    };
    std::error_code ec;
    fs::path p = fs::absolute(dir, ec);
    if (fs::exists(p, ec) && !fs::is_directory(p, ec)) return fail("exists and is not a folder");
    // The nearest folder that exists must take a new file: probe it (a permission bit alone
    // does not tell, e.g. /proc refuses root).
    fs::path base = p;
    while (!fs::exists(base, ec) && base.has_parent_path() && base.parent_path() != base) base = base.parent_path();
    if (!fs::is_directory(base, ec)) return fail(base.string() + " is not a folder");
    fs::path probe = base / (".passlab-write-probe-" + std::to_string(::getpid()));
    std::FILE* f = std::fopen(probe.c_str(), "wb");
    if (!f) return fail("cannot create files in " + base.string() + " (" + std::strerror(errno) + ")");
    std::fclose(f);
    fs::remove(probe, ec);
    return ok_status();
}

} // namespace

Status check_output_dir(const std::string& dir, const std::string& flag) { return check_writable_dir(dir, flag + " " + dir); }

Status check_output_file(const std::string& file, const std::string& flag) {
    namespace fs = std::filesystem;
    std::error_code ec;
    if (fs::is_directory(file, ec)) {
        Error e = make_error(flag + " " + file + ": is a folder, not a file");
        e.code = ExitCode::environment;
        return e;
    }
    return check_writable_dir(fs::absolute(file, ec).parent_path().string(), flag + " " + file);
}

} // namespace pl::lab
