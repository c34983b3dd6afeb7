#version 450
layout(location = 0) out vec4 color;
void main() { color = vec4(float(pl_iteration), float(pl_iteration_count), 0.0, 1.0); }
