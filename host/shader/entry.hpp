// The Shadertoy entry point: a fragment shader that defines mainImage(out vec4, in vec2) and no
// main() gets a main() calling it (docs/format.md, "Shaders see").
#pragma once

#include <string>

namespace pl::shader {

// What to append to an expanded fragment source: empty when it defines main() or no mainImage.
// fragCoord is gl_FragCoord.xy (top-left origin, the host's convention; `passlab import`
// generates its own bottom-left main for Shadertoy sources).
std::string main_image_entry(const std::string& expanded);

} // namespace pl::shader
