#version 450
// Measures the mesh's tangent frames for the tests. For every corner of every triangle it emits
// one triangle covering the whole 2 x 1 `stats` target (blend max), carrying flat values that
// the fragment shader writes; the target ends up holding the maximum over all vertices of
//   texel 0: |T.N|,  w,  -w,  | |T| - 1 |              (the host's per-vertex frame)
//   texel 1: 1 - T_tri.T (T_tri made orthogonal to the vertex N),  |T_tri - (1, 0, 0)|,
//            |T - (1, 0, 0)|,  |w_tri - w|             (against 001's per-triangle formula)
// so max w and max -w are both -1 and 1 only if every vertex has the same handedness.
#include "bump/triangle_frame.glsl"
layout(triangles) in;
layout(triangle_strip, max_vertices = 9) out;
layout(location = 0) in vec3 v_world[];
layout(location = 1) in vec2 v_uv[];
layout(location = 2) in vec3 v_t[];
layout(location = 3) in vec3 v_b[];
layout(location = 4) in vec3 v_n[];
layout(location = 0) flat out vec4 g_vertex;
layout(location = 1) flat out vec4 g_triangle;

const float kPoleNy = 0.999;   // |N.y| above this: a vertex of a pole row (within 2.6 degrees of the axis)

void main() {
    if (!(VISIBLE)) return;
    mat2x3 d = triangle_pu_pv(v_world[0], v_world[1], v_world[2], v_uv[0], v_uv[1], v_uv[2]);
    if (dot(d[0], d[0]) == 0.0) return;   // no uv area: no frame to compare with
    vec3 T_tri = normalize(d[0]);
    for (int i = 0; i < 3; ++i) {
        vec3 N = v_n[i], T = v_t[i];
        // The pole rows of the sphere (and the teapot's knob and bottom centre) have P_u = 0:
        // no tangent exists there, the host picks an arbitrary one. Tests may leave them out.
        if (params.exclude_poles && abs(N.y) > kPoleNy) continue;
        float w = dot(v_b[i], cross(N, T)) < 0.0 ? -1.0 : 1.0;   // tangent_space.vert: B = (N x T) w
        vec3 Tg = normalize(T_tri - dot(T_tri, N) * N);           // Gram-Schmidt against N
        float w_tri = frame_handedness(N, Tg, d[1]);
        vec4 a = vec4(abs(dot(T, N)), w, -w, abs(length(T) - 1.0));
        vec4 b = vec4(1.0 - dot(Tg, normalize(T)), length(T_tri - vec3(1, 0, 0)), length(T - vec3(1, 0, 0)), abs(w_tri - w));
        // One triangle over the whole target (clip space (-1,-1), (3,-1), (-1,3)); outputs are
        // undefined after EmitVertex, so they are written again for every vertex.
        const vec2 kCorners[3] = vec2[](vec2(-1.0, -1.0), vec2(3.0, -1.0), vec2(-1.0, 3.0));
        for (int k = 0; k < 3; ++k) {
            g_vertex = a, g_triangle = b;
            gl_Position = vec4(kCorners[k], 0.0, 1.0);
            EmitVertex();
        }
        EndPrimitive();
    }
}
