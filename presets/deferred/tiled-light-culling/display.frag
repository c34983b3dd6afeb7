#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D lit;
void main() { ldr = vec4(clamp(texture(lit, uv).rgb, 0.0, 1.0), 1.0); }
