// `passlab import`: Shadertoy (API JSON, a mainImage file, a folder of tabs) and ISF (.fs with
// its JSON header, and the .vs beside it) turned into ordinary preset folders (docs/import.md).
#pragma once

#include "import/preset_files.hpp"

#include <filesystem>
#include <optional>
#include <string>

namespace pl::import {

enum class SourceKind { shadertoy_json, shadertoy_file, shadertoy_folder, isf };

struct ImportOptions {
    std::string kind;     // "", "shadertoy" or "isf" (--kind): forces the family
    bool golden = true;   // a [[test]] golden case at a pinned time and date; else a `stable` case
};

// What `path` is, or nullopt when it is not an import source (a preset, a .toml ...).
// `forced` ("shadertoy"/"isf") decides for files whose kind the name and content leave open.
std::optional<SourceKind> detect_source(const std::filesystem::path& path, const std::string& forced = {});

// Reads the source and generates the preset's files.
Result<PresetFiles> import_source(const std::filesystem::path& path, const ImportOptions& o);

// A Shadertoy shader as a preset (used by import_source; public for the unit tests).
struct Toy;
Result<PresetFiles> shadertoy_preset(const Toy& toy, const ImportOptions& o);
// An ISF .fs (and the .vs beside it) as a preset.
Result<PresetFiles> import_isf(const std::filesystem::path& fs_file, const ImportOptions& o);

} // namespace pl::import
