#version 450
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 g_position;  // xyz world, w = 1 on a surface (0: sky)
layout(location = 1) out vec4 g_normal;    // xyz normal facing the eye, w = MESH
void main() {
    vec3 n = normalize(v_normal);
    if (dot(n, frame.camera_pos.xyz - v_world) < 0.0) n = -n;  // the teapot's inside seen through its spout
    g_position = vec4(v_world, 1.0);
    g_normal = vec4(n, float(MESH));
}
