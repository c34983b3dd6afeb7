#include "import/preset_files.hpp"

#include <fstream>

namespace pl::import {

namespace fs = std::filesystem;

Status write_preset(const PresetFiles& p, const fs::path& dest, bool replace) {
    std::error_code ec;
    if (!replace && fs::exists(dest, ec)) {
        Error e = make_error("'" + dest.string() + "' already exists; passlab import never overwrites");
        e.hint = "choose a new folder for -o";
        e.code = ExitCode::usage;
        return e;
    }
    fs::create_directories(dest, ec);
    if (ec) {
        Error e = make_error("cannot create '" + dest.string() + "': " + ec.message());
        e.code = ExitCode::environment;
        return e;
    }
    for (const auto& [name, text] : p.files) {
        const fs::path f = dest / name;
        fs::create_directories(f.parent_path(), ec);
        std::ofstream out(f, std::ios::binary | std::ios::trunc);
        out << text;
        if (!out) {
            Error e = make_error("cannot write '" + f.string() + "'");
            e.code = ExitCode::environment;
            return e;
        }
    }
    for (const auto& [name, from] : p.copies) {
        const fs::path f = dest / name;
        fs::create_directories(f.parent_path(), ec);
        fs::copy_file(from, f, fs::copy_options::overwrite_existing, ec);
        if (ec) {
            Error e = make_error("cannot copy '" + from.string() + "' to '" + f.string() + "': " + ec.message());
            e.code = ExitCode::environment;
            return e;
        }
    }
    return ok_status();
}

} // namespace pl::import
