#include "sources.hpp"

#include "exec/build.hpp"

#include <cstdio>
#include <cstdlib>
#include <unistd.h>

namespace fs = std::filesystem;

namespace pl::lab {

namespace {

// Scratch folders live under the temp directory and go when the process ends.
struct Registry {
    std::vector<ScratchImport> imports;
    ~Registry() {
        std::error_code ec;
        for (const auto& s : imports) fs::remove_all(s.dir, ec);
    }
};
Registry& registry() {
    static Registry r;
    return r;
}

Status import_into(ScratchImport& si, bool print_warnings) {
    auto files = import::import_source(si.source, si.options);
    if (!files) return files.error();
    if (auto s = import::write_preset(*files, si.dir, true); !s) return s.error();
    si.origins = files->origins;
    si.inputs = files->inputs;
    if (print_warnings)
        for (const auto& w : files->warnings) std::fprintf(stderr, "import: warning: %s\n", w.c_str());
    return ok_status();
}

} // namespace

Result<fs::path> resolve_source(const std::string& arg) {
    if (!import::detect_source(arg)) return exec::resolve_preset(arg);
    std::string tmpl = (fs::temp_directory_path() / "passlab-import-XXXXXX").string();
    if (!mkdtemp(tmpl.data())) {
        Error e = make_error("cannot create a scratch folder in " + fs::temp_directory_path().string());
        e.code = ExitCode::environment;
        return e;
    }
    ScratchImport si;
    si.source = arg;  // as the user wrote it: errors in the JSON name it that way
    si.dir = tmpl;
    si.options.golden = false;  // a golden recorded into a scratch folder would compare nothing
    registry().imports.push_back(si);
    if (auto s = import_into(registry().imports.back(), true); !s) return s.error();
    std::fprintf(stderr, "import: %s -> %s\n", arg.c_str(), tmpl.c_str());
    return fs::path(tmpl) / "preset.toml";
}

const std::vector<ScratchImport>& scratch_imports() { return registry().imports; }

Status reimport(ScratchImport& si) {
    for (auto& r : registry().imports)
        if (r.dir == si.dir) return import_into(r, false);
    return import_into(si, false);
}

std::string map_scratch_text(std::string s) {
    std::error_code ec;
    for (const auto& si : registry().imports) {
        // The compiler shows files relative to the working folder when it can: map that form
        // and the absolute one (longest first: the relative form ends with the absolute tail).
        for (const fs::path& dir : {fs::proximate(si.dir, ec), si.dir}) {
            const std::string prefix = dir.string() + "/";
            for (const auto& [file, origin] : si.origins) {
                const std::string full = prefix + file;
                const std::string shown = fs::path(origin).is_absolute() ? fs::proximate(origin, ec).string() : origin;
                for (size_t at; (at = s.find(full)) != std::string::npos;) s.replace(at, full.size(), shown);
            }
        }
    }
    return s;
}

std::string preset_name(const fs::path& dir) {
    for (const auto& si : registry().imports)
        if (fs::path(dir).lexically_normal() == si.dir.lexically_normal()) return si.source.stem().string();
    return dir.filename().string();
}

Error map_scratch_error(Error e) {
    e.loc.file = map_scratch_text(e.loc.file);
    e.message = map_scratch_text(e.message);
    for (auto& n : e.notes) n = map_scratch_text(n);
    return e;
}

} // namespace pl::lab
