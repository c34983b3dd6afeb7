// Saved param values: the panel writes the values the user set to a sidecar file next to the
// preset (`preset.params.toml`), which the next `passlab run` of that preset applies before any
// `--set`. The user's preset.toml is never written. Only `run` reads it: `render` and `test`
// stay reproducible from the preset alone.
#pragma once

#include "graph/desc.hpp"
#include "util/error.hpp"

#include <array>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace pl::exec {

std::filesystem::path sidecar_path(const std::filesystem::path& preset_toml);

// Writes `name = value` lines (TOML) atomically (temp file + rename).
Status save_sidecar(const std::filesystem::path& file, const std::vector<graph::ParamDesc>& params,
                    const std::map<std::string, std::array<double, 4>>& values);

// Reads a sidecar into `--set` style assignments ("name=v1,v2"); errors name file:line.
Result<std::vector<std::string>> load_sidecar(const std::filesystem::path& file);

// One param value in `--set` syntax (enum: its option name; bool: true/false).
std::string format_param_value(const graph::ParamDesc& p, const std::array<double, 4>& v);

} // namespace pl::exec
