#version 450
layout(location = 0) flat in vec4 g_vertex;
layout(location = 1) flat in vec4 g_triangle;
layout(location = 0) out vec4 stats;
void main() { stats = int(gl_FragCoord.x) == 0 ? g_vertex : g_triangle; }
