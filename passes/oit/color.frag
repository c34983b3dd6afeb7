#version 450
// Flat colour of the shared OIT scene (quads.vert): the opaque pass.
layout(location = 0) flat in vec4 v_color;
layout(location = 0) out vec4 color;
void main() { color = v_color; }
