#version 450
layout(location = 0) out vec4 color;
void main() { color = vec4(0.97, 0.96, 0.93, 1.0); }
