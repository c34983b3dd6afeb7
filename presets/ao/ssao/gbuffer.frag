#version 450
// The G-buffer SSAO needs (003 L341, 004 L719-720): view-space normal and position, and the
// view depth z once more alone (the occluder test reads only that).
layout(location = 0) in vec3 v_view_pos;
layout(location = 1) in vec3 v_view_normal;
layout(location = 0) out vec4 normal;
layout(location = 1) out vec4 vpos;
layout(location = 2) out float vz;
void main() {
    vec3 n = normalize(v_view_normal);
    // Two-sided surfaces (the walls): the normal of the side facing the eye.
    if (dot(n, -v_view_pos) < 0.0) n = -n;
    normal = vec4(n, 1.0);
    vpos = vec4(v_view_pos, 1.0);
    vz = v_view_pos.z;
}
