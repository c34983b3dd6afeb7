#version 450
// The noise mapped [-1, 1] -> [0, 1]; "compare" puts 3D value noise (common/noise.glsl, remapped)
// on the left; "lattice" draws the simplex triangles over it.
#include "common/noise.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D field;
void main() {
    float v = texture(field, uv).r * 0.5 + 0.5;
    vec2 p = (uv - 0.5) * vec2(frame.aspect, 1.0) * params.frequency;
    if (params.view_mode == VIEW_MODE_COMPARE && uv.x < 0.5) v = value_noise(vec3(p, 0.5));
    vec3 c = vec3(v);
    if (params.view_mode == VIEW_MODE_LATTICE) {
        vec2 s = p + (p.x + p.y) * kSimplexF2;  // skewed: triangle edges are where fract hits 0 or x = y
        vec2 f = fract(s);
        float edge = min(min(f.x, f.y), min(1.0 - max(f.x, f.y), abs(f.x - f.y)));
        if (edge < 0.02) c = vec3(1.0, 0.5, 0.1);
    }
    if (params.view_mode == VIEW_MODE_COMPARE && abs(uv.x - 0.5) < 0.0015) c = vec3(1.0, 0.8, 0.2);
    ldr = vec4(c, 1.0);
}
