#version 450
// Test helper: shows the image bound as `src` (use bind = { src = "name" }).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D src;
void main() { color = texture(src, uv); }
