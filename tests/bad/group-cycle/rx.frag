#version 450
layout(location = 0) out vec4 color;
uniform sampler2D x;
void main() { color = texture(x, vec2(0.5)); }
