#version 450
// Face k of the cube gets the value (k + 1)/8.
layout(location = 0) out vec4 color;
void main() { color = vec4(float(pl_iteration + 1) / 8.0); }
