#version 450
// Displacement mapping with prisms (004_9a40ad89bdfc582a.txt L1048-1052: "geometry shader
// extrudes prism at each face; fragment shader ray-casts against height field; shade or discard
// pixel depending on ray test"). For each triangle the geometry shader emits the prism between
// the triangle and its copy lifted by params.height along the vertex normals (q_i = p_i +
// n_i height): the top and three side quads (the bottom is the surface itself: a ray from
// outside cannot enter there). Neighbouring prisms share their side faces exactly (the same
// corners, the quads split along the same diagonal: prism_faces.glsl), so together they fill
// the shell without gaps or overlaps.
// The ray is followed in texture space (u, v, w), w = 0 on the triangle, 1 at the top, through
// the triangle's affine map
//     P(u, v, w) = p0 + P_u (u - u0) + P_v (v - v0) + N_f height w
// with [P_u P_v] = [v1 v2][u1 u2]^-1, the triangle's own frame (001_fe43b953f362fae7.txt
// L819-855, passes/bump/triangle_frame.glsl), and N_f its face normal. The map is exact on the
// triangle (w = 0) and approximate above it, where the lifted prism leans with the vertex
// normals. M = [P_u P_v N_f height], the corners and vertex normals go flat to the fragment
// shader.
#include "bump/triangle_frame.glsl"
#include "prism_faces.glsl"
layout(triangles) in;
layout(triangle_strip, max_vertices = 15) out;
layout(location = 0) in vec3 v_world[];
layout(location = 1) in vec2 v_uv[];
layout(location = 2) in vec3 v_t[];
layout(location = 3) in vec3 v_b[];
layout(location = 4) in vec3 v_n[];
layout(location = 0) out vec3 g_world;
layout(location = 1) out vec3 g_uvw;
layout(location = 2) flat out mat3 g_m;       // locations 2-4
layout(location = 5) flat out vec3 g_p0;
layout(location = 6) flat out vec4 g_uv01;
layout(location = 7) flat out vec2 g_uv2;
layout(location = 8) flat out vec3 g_n0;
layout(location = 9) flat out vec3 g_n1;
layout(location = 10) flat out vec3 g_n2;
layout(location = 11) flat out vec3 g_p1;
layout(location = 12) flat out vec3 g_p2;

mat3 m;
vec3 p0;
vec4 uv01;
vec2 uv2;
vec3 n0, n1, n2;

void emit(int i, float w) {
    vec3 lift = normalize(v_n[i]) * params.height * w;
    g_world = v_world[i] + lift;
    g_uvw = vec3(v_uv[i], w);
    g_m = m, g_p0 = p0, g_uv01 = uv01, g_uv2 = uv2, g_n0 = n0, g_n1 = n1, g_n2 = n2;
    g_p1 = v_world[1], g_p2 = v_world[2];
    gl_Position = frame.view_proj * vec4(g_world, 1.0);
    EmitVertex();
}

void main() {
    // Two passes share this shader, one per tessellation of the torus (preset.toml): only the one
    // that mesh_detail selects emits prisms.
    if (params.mesh_detail != PRISM_MESH) return;
    mat2x3 d = triangle_pu_pv(v_world[0], v_world[1], v_world[2], v_uv[0], v_uv[1], v_uv[2]);
    if (dot(d[0], d[0]) == 0.0) return;   // degenerate: no surface, no prism
    vec3 N_f = normalize(cross(v_world[1] - v_world[0], v_world[2] - v_world[0]));
    m = mat3(d[0], d[1], N_f * max(params.height, 1e-5));   // height 0 would make M singular
    p0 = v_world[0], uv01 = vec4(v_uv[0], v_uv[1]), uv2 = v_uv[2];
    n0 = v_n[0], n1 = v_n[1], n2 = v_n[2];
    // Top, counter-clockwise seen from outside like the triangle.
    emit(0, 1.0); emit(1, 1.0); emit(2, 1.0);
    EndPrimitive();
    // Sides: edge i -> j of the counter-clockwise triangle, quad (p_i, p_j, p_j', p_i') faces out.
    for (int e = 0; e < 3; ++e) {
        int i = e, j = (e + 1) % 3;
        if (prism_diagonal_from_i(v_world[i], v_world[j])) { emit(i, 1.0); emit(i, 0.0); emit(j, 1.0); emit(j, 0.0); }
        else { emit(i, 0.0); emit(j, 0.0); emit(i, 1.0); emit(j, 1.0); }
        EndPrimitive();
    }
}
