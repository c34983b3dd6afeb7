#version 450
// The base mesh drawn directly (no tessellation): the reference for zero displacement.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 g_world;
layout(location = 1) out vec3 g_normal;
void main() {
    g_world = position;
    g_normal = normal;
    gl_Position = frame.view_proj * vec4(position, 1.0);
}
