#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D single;
void main() { vec3 c = texture(single, uv).rgb; ldr = vec4(c / (1.0 + c), 1.0); }
