#version 450
// The split-sum table of envmap/ibl-brdf-lut (x roughness, y n.v), 64 x 64, 1024 samples.
#include "envmap/brdf_lut.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec2 lut;
void main() { lut = integrate_brdf(uv.x, uv.y, 1024); }
