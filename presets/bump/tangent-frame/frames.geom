#version 450
// The tangent frames as line glyphs (red T, green B, blue N), from a geometry shader that sees
// whole triangles:
//   FRAMES_TRIANGLE: one frame per triangle at its centroid, computed here from the triangle's
//     positions and uvs with 001_fe43b953f362fae7.txt L819-855 (passes/bump/triangle_frame.glsl):
//     [P_u P_v] = [v1 v2][u1 u2]^-1, T = P_u / |P_u|, N_n the face normal, B = (N_n x T) w;
//   FRAMES_VERTEX: the mesh's own per-vertex frame (the host's average over the triangles
//     around each vertex, 001 L857-862) at each corner.
// The input is bump/tangent_space.vert's: world position, uv, T, B = (N x T) w, N.
#include "bump/triangle_frame.glsl"
layout(triangles) in;
layout(line_strip, max_vertices = 18) out;
layout(location = 0) in vec3 v_world[];
layout(location = 1) in vec2 v_uv[];
layout(location = 2) in vec3 v_t[];
layout(location = 3) in vec3 v_b[];
layout(location = 4) in vec3 v_n[];
layout(location = 0) out vec3 g_color;

const float kLift = 0.004;   // glyphs start this far above the surface, so the depth test keeps them

void segment(vec3 a, vec3 dir, vec3 color) {
    g_color = color;
    gl_Position = frame.view_proj * vec4(a, 1.0);
    EmitVertex();
    g_color = color;
    gl_Position = frame.view_proj * vec4(a + dir * params.glyph_length, 1.0);
    EmitVertex();
    EndPrimitive();
}
void glyph(vec3 p, vec3 T, vec3 B, vec3 N) {
    p += N * kLift;
    segment(p, T, vec3(1.0, 0.1, 0.1));
    segment(p, B, vec3(0.1, 1.0, 0.1));
    segment(p, N, vec3(0.2, 0.4, 1.0));
}
void main() {
    if (!(VISIBLE) || params.frames == FRAMES_NONE) return;
    if (params.frames == FRAMES_TRIANGLE) {
        mat2x3 d = triangle_pu_pv(v_world[0], v_world[1], v_world[2], v_uv[0], v_uv[1], v_uv[2]);
        if (dot(d[0], d[0]) == 0.0) return;
        vec3 N = normalize(cross(v_world[1] - v_world[0], v_world[2] - v_world[0]));
        vec3 T = normalize(d[0]);
        vec3 B = cross(N, T) * frame_handedness(N, T, d[1]);
        glyph((v_world[0] + v_world[1] + v_world[2]) / 3.0, T, B, N);
    } else {
        for (int i = 0; i < 3; ++i) glyph(v_world[i], normalize(v_t[i]), normalize(v_b[i]), normalize(v_n[i]));
    }
}
