// An imported preset before it is written: file contents by relative name, files to copy, and
// where errors in each generated file should point (a tab label or the user's own file).
#pragma once

#include "util/error.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace pl::import {

struct PresetFiles {
    std::map<std::string, std::string> files;            // "preset.toml", "buffer_a.glsl", ...
    std::map<std::string, std::filesystem::path> copies;  // "media/photo.png" <- the user's file
    std::map<std::string, std::string> origins;           // "buffer_b.glsl" -> "Buffer B" or "/x/buffer_b.glsl"
    std::vector<std::string> warnings;                    // one line each
    std::vector<std::filesystem::path> inputs;            // the user's files (run watches them)
};

// Writes every file into `dest`. Without `replace`, `dest` must not exist (import never
// overwrites); with it (a scratch folder passlab owns) the files are rewritten in place.
Status write_preset(const PresetFiles& p, const std::filesystem::path& dest, bool replace);

} // namespace pl::import
