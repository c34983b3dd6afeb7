#version 450
// The LUT: x = roughness, y = n.v (texel centres, as 002's fragCoord / resolution), b = r + g.
#include "envmap/brdf_lut.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 lut;
void main() {
    vec2 r = integrate_brdf(uv.x, uv.y, params.samples);
    lut = vec4(r, r.x + r.y, 1.0);
}
