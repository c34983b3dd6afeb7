#version 450
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D albdo;
void main() { color = texture(albdo, uv); }
