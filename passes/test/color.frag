#version 450
// Test helper: writes the flat colour of passes/test/quad.vert.
layout(location = 0) flat in vec4 v_color;
layout(location = 0) out vec4 color;
void main() { color = v_color; }
