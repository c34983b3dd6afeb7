// `--set NAME=FILE` where NAME is an image: a file or generator image takes its pixels from the
// user's FILE instead. This is how a picture reaches an ISF image input, a Shadertoy channel's
// procedural stand-in (image `<pass>_ch<N>`), or any preset's texture, without editing the
// preset (an imported source run directly lives in a scratch folder the user never sees).
#pragma once

#include "graph/desc.hpp"
#include "util/error.hpp"

#include <optional>
#include <string>

namespace pl::exec {

// nullopt when `assignment` ("name=value") does not name an image of `g` (or names a param:
// params come first), so the caller treats it as a param override. Otherwise the override is
// applied, or an error says why it cannot be (a rendered image, a cube or 3D image, no such file).
// The image keeps its sampler, format, srgb, flip_y and mips; a relative FILE is taken from the
// current directory, as every other command-line path.
std::optional<Status> apply_image_override(graph::GraphDesc& g, const std::string& assignment);

} // namespace pl::exec
