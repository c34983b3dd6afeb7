#version 450
layout(location = 0) out vec4 color;
uniform sampler2D y;
void main() { color = texture(y, vec2(0.5)); }
