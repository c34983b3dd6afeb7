#version 450
// Mesh -> tangent space for the bump presets (000_c9f7e5de708ecbb3.txt L2490-2553): world
// position, uv, and the tangent frame T, B = (N x T) * w, N (w: the tangent's handedness sign,
// location 3's w) so the fragment shader can bring l, v, h into tangent space or normals out.
// The mesh is placed by ROTATION (a mat3 expression; default identity).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 3) in vec4 tangent;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec2 v_uv;
layout(location = 2) out vec3 v_t;
layout(location = 3) out vec3 v_b;
layout(location = 4) out vec3 v_n;
mat3 rot_x(float a) { return mat3(1, 0, 0, 0, cos(a), sin(a), 0, -sin(a), cos(a)); }
#ifndef ROTATION
#define ROTATION mat3(1.0)
#endif
void main() {
    mat3 m = ROTATION;
    v_world = m * position;
    v_uv = uv;
    v_n = m * normal;
    v_t = m * tangent.xyz;
    v_b = cross(v_n, v_t) * tangent.w;  // 001 L801-862 / catalogue pitfall: b = n x t, times handedness
    gl_Position = frame.view_proj * vec4(v_world, 1.0);
}
