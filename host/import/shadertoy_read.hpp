// Readers of the three Shadertoy source forms; each returns the same Toy.
#pragma once

#include "import/toy.hpp"

#include <filesystem>

namespace pl::import {

// The API JSON: {"Shader": {...}}, the bare inner object, or an array of them (the first is used).
Result<Toy> read_shadertoy_json(const std::filesystem::path& file);
// A .glsl/.frag holding the Image tab (mainImage); no channels.
Result<Toy> read_shadertoy_file(const std::filesystem::path& file);
// A folder: image.glsl, optional common.glsl, buffer_a.glsl .. buffer_d.glsl, cube_a.glsl,
// sound.glsl, and optional channels.toml wiring the iChannels (docs/import.md).
Result<Toy> read_shadertoy_folder(const std::filesystem::path& dir);

} // namespace pl::import
