#version 450
// A black/white checker written to two 8-bit targets: a UNORM one (what is written is stored)
// and an sRGB one (linear values encoded on store). Both hold the same bytes: 0 and 1 encode to
// themselves, and a grey light cell (params.light < 1) is decoded first so the sRGB target's
// encoding gives its stored value back.
#include "common/color.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 checker_unorm;
layout(location = 1) out vec4 checker_srgb;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy) / params.cells;
    vec3 v = vec3(float((p.x + p.y) & 1) * params.light);
    checker_unorm = vec4(v, 1.0);
    checker_srgb = vec4(srgb_to_linear(v), 1.0);
}
