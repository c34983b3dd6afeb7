#version 450
#include "shared.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D prev;
void main() { color = vec4(shade(texture(prev, uv).rgb, float(STAGE)), 1.0); }
