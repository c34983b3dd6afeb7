// Arguments that are Shadertoy or ISF sources rather than presets: every verb imports them into a
// scratch folder passlab owns (never beside the user's file) and runs that preset; errors in the
// generated files are reported at the user's tab or file.
#pragma once

#include "import/import.hpp"
#include "util/error.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace pl::lab {

struct ScratchImport {
    std::filesystem::path source;             // the user's file or folder
    std::filesystem::path dir;                // the scratch preset folder
    import::ImportOptions options;
    std::map<std::string, std::string> origins;  // scratch file name -> where errors point
    std::vector<std::filesystem::path> inputs;   // the user's files (run watches them)
};

// preset.toml of `arg`: a preset as exec::resolve_preset finds it, or the scratch import of a
// Shadertoy/ISF source (warnings printed once).
Result<std::filesystem::path> resolve_source(const std::string& arg);
// The imports made by this process (run watches their inputs and re-imports on a change).
const std::vector<ScratchImport>& scratch_imports();
// Imports `si.source` again into its scratch folder (run: the user edited the source).
Status reimport(ScratchImport& si);
// Replaces scratch paths in an error by the user's tab or file.
Error map_scratch_error(Error e);
std::string map_scratch_text(std::string s);
// The name a preset folder is shown and saved by: the source's stem for a scratch import
// (`render toy.json` writes toy.png), else the folder's name.
std::string preset_name(const std::filesystem::path& dir);

} // namespace pl::lab
