#version 450
// Test helper: writes the constant VALUE (a define), for blend and load/store graphs.
layout(location = 0) out vec4 color;
void main() { color = VALUE; }
