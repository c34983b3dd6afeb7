#version 450
// A camera pass: frame.resolution is its render area (and frame.target the same).
layout(location = 0) out vec4 color;
void main() { color = frame.resolution == frame.target ? frame.resolution : vec4(-1.0); }
