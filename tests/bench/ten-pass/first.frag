#version 450
#include "shared.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() { color = vec4(shade(vec3(uv, 0.5), float(STAGE)), 1.0); }
