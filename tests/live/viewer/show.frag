#version 450
// The preset's own output (what the window shows without the viewer): the cells, magnified.
layout(binding = 0) uniform sampler2D cells;
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 o;
void main() { o = texture(cells, uv); }
