// `passlab new DEST --from PRESET`: start a preset from a copy of another one.
//
// The copy is a plain folder the user owns: every file of the source preset folder (shaders,
// README, goldens, files), so `passlab run DEST` works at once and its tests still pass.
// `--with-passes` also copies the files the preset reads from the shared passes/ library into
// DEST at the same relative path; shader lookup tries the preset folder before passes/, so those
// copies shadow the library and can be edited without touching other presets.
//
// `passlab new DEST --exercise PRESET` copies only the preset's exercise/ folder (the files with
// TODO blocks and their README): the student edits DEST, never the shipped reference, and runs
// and grades it with `--exercise DEST`.
//
// Never overwrites: DEST must not exist (the host writes user files only where asked).
#include "verbs.hpp"
#include "sources.hpp"
#include "util/paths.hpp"

#include <cstdio>
#include <filesystem>
#include <system_error>

namespace fs = std::filesystem;

namespace pl::lab {
namespace {

Error usage_error(std::string msg) {
    Error e = make_error(std::move(msg));
    e.code = ExitCode::usage;
    return e;
}

Error env_error(std::string msg) {
    Error e = make_error(std::move(msg));
    e.code = ExitCode::environment;
    return e;
}

// Copies every regular file under src into the new folder dest (created here); returns the count.
Result<int> copy_tree(const fs::path& src, const fs::path& dest, const fs::path& skip = {}) {
    std::error_code ec;
    fs::create_directories(dest.parent_path().empty() ? fs::path(".") : dest.parent_path(), ec);
    if (!fs::create_directory(dest, ec) || ec)
        return env_error("passlab new: cannot create '" + dest.string() + "': " + ec.message());
    int copied = 0;
    for (auto it = fs::recursive_directory_iterator(src, ec); !ec && it != fs::recursive_directory_iterator();
         it.increment(ec)) {
        const auto rel = it->path().lexically_relative(src);
        if (!skip.empty() && rel == skip) continue;
        if (it->is_directory()) {
            fs::create_directories(dest / rel, ec);
        } else if (it->is_regular_file()) {
            fs::copy_file(it->path(), dest / rel, fs::copy_options::none, ec);
            ++copied;
        }
        if (ec) break;
    }
    if (ec) return env_error("passlab new: copying " + src.string() + " failed: " + ec.message());
    return copied;
}

int new_exercise(const NewOptions& o, const fs::path& dest) {
    auto toml = resolve_source(o.exercise);
    if (!toml) return report(toml.error());
    const fs::path ex = toml->parent_path() / "exercise";
    std::error_code ec;
    if (!fs::is_directory(ex, ec))
        return report(usage_error("passlab new --exercise: " + toml->parent_path().string() +
                                  " has no exercise/ folder (`passlab list --course` shows which presets have one)"));
    if (path_within(dest, toml->parent_path()))
        return report(usage_error("passlab new: '" + dest.string() + "' lies inside the preset " +
                                  toml->parent_path().string() + " (work outside the shipped reference)"));
    auto copied = copy_tree(ex, dest);
    if (!copied) return report(copied.error());
    std::printf("copied %d exercise files of %s into %s\n", *copied, toml->parent_path().string().c_str(),
                dest.string().c_str());
    std::printf("next: read %s/README.md, then\n  passlab run   %s --exercise %s\n  passlab grade %s --exercise %s\n",
                dest.string().c_str(), o.exercise.c_str(), dest.string().c_str(), o.exercise.c_str(),
                dest.string().c_str());
    return 0;
}

} // namespace

int new_preset(const NewOptions& o, const CommonOptions& c) {
    if (o.dest.empty()) return report(usage_error("passlab new: DEST is empty"));
    fs::path dest = o.dest;
    std::error_code ec;
    if (fs::exists(dest, ec) || fs::is_symlink(dest, ec))
        return report(usage_error("passlab new: '" + dest.string() +
                                  "' already exists; passlab never overwrites files (choose a new folder)"));

    if (!o.exercise.empty()) return new_exercise(o, dest);
    if (o.from.empty()) return report(usage_error("passlab new DEST needs --from PRESET (or --exercise PRESET)"));
    auto toml = resolve_source(o.from);
    if (!toml) return report(toml.error());
    const fs::path src = toml->parent_path();

    // Build the source first: a broken source is reported here, not discovered after copying,
    // and the build lists every file the preset reads (for --with-passes).
    exec::BuildOptions bo;
    bo.cache_dir = cache_dir(c);
    auto built = exec::build_graph(*toml, bo);
    if (!built) return report(built.error());

    if (path_within(dest, src))
        return report(usage_error("passlab new: '" + dest.string() + "' lies inside the source preset " +
                                  src.string()));

    // The param sidecar holds someone's slider positions, not part of the preset.
    auto copied = copy_tree(src, dest, "preset.params.toml");
    if (!copied) return report(copied.error());
    std::printf("copied %d files of %s into %s\n", *copied, src.string().c_str(), dest.string().c_str());

    if (o.with_passes) {
        const fs::path lib = exec::passes_dir();
        int shadowed = 0;
        for (const auto& dep : built->dependencies) {
            const auto within = path_within(dep, lib);
            if (!within) continue;
            const fs::path& rel = *within;
            fs::create_directories((dest / rel).parent_path(), ec);
            if (!ec) fs::copy_file(dep, dest / rel, fs::copy_options::skip_existing, ec);
            if (ec) return report(env_error("passlab new: copying " + dep.string() + " failed: " + ec.message()));
            std::printf("  passes/%s -> %s\n", rel.string().c_str(), (dest / rel).string().c_str());
            ++shadowed;
        }
        std::printf("copied %d files of passes/ (they shadow the library for this preset)\n", shadowed);
    }
    std::printf("next: passlab run %s\n", dest.string().c_str());
    return 0;
}

} // namespace pl::lab
