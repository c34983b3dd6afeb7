#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D accum_prev;   // last frame's accum (zero on the first frame)
void main() { color = texture(accum_prev, uv) + 1.0; }
