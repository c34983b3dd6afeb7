#version 450
// Writes a vertex's position and normal into its texel (points.vert).
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in float v_id;
layout(location = 0) out vec4 g_position;
layout(location = 1) out vec4 g_normal;
void main() {
    g_position = vec4(v_world, 1.0);
    g_normal = vec4(normalize(v_normal), v_id);
}
