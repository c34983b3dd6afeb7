#version 450
layout(location = 0) out vec4 color;
void main() { color = vec4(0.45, 0.36, 0.25, 1.0); }
