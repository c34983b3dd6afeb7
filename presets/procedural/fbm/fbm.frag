#version 450
// Fractal Brownian motion, one fragment per pixel: the sum lives in fbm.glsl (equation and
// sources there).
#include "fbm.glsl"

layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 field;

void main() { field = fbm_field(uv); }
