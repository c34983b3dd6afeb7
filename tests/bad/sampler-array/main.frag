#version 450
layout(location = 0) out vec4 color;
// Two images through one array binding: not expressible in the graph (one resource per name).
uniform sampler2D pattern[2];
void main() { color = texture(pattern[1], vec2(0.5)); }
