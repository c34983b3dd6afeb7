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
layout(location = 13) flat out mat3 g_m_inv;   // locations 13-15: M^-1 once per prism, not per fragment
uniform sampler2D occluder_tiles;   // farthest base-mesh depth per kTile x kTile pixels (occluder_tiles.frag)

mat3 m, m_inv;
vec3 p0;
vec4 uv01;
vec2 uv2;
vec3 n0, n1, n2;

void emit(int i, float w) {
    vec3 lift = normalize(v_n[i]) * params.height * w;
    g_world = v_world[i] + lift;
    g_uvw = vec3(v_uv[i], w);
    g_m = m, g_m_inv = m_inv, g_p0 = p0, g_uv01 = uv01, g_uv2 = uv2, g_n0 = n0, g_n1 = n1, g_n2 = n2;
    g_p1 = v_world[1], g_p2 = v_world[2];
    gl_Position = frame.view_proj * vec4(g_world, 1.0);
    EmitVertex();
}

// Occlusion cull (for speed; it changes no pixel): true when no fragment of this prism can be
// nearer than the relief already is. Every point of the prism lies in the convex hull of its six
// corners, so its fragments lie inside their projected bounding box and no nearer than the
// nearest corner (depth is monotone in view distance). Each of those pixels' nearest hit is no
// farther than its base-mesh depth (occluder_tiles.frag), hence no farther than the tile's
// farthest. kOccluderMargin (depth units; ~7 mm at the default distance, d(depth)/dz = 0.014 per
// unit) covers the rounding between rasterised and computed depths (measured 6e-7 between the
// prisms' hit and the base mesh, zero-height-is-base-mesh). A prism outside the view is dropped
// too; one whose box spans more than kMaxTiles tiles per side, or crosses the eye plane, is kept.
const int kTile = 8, kMaxTiles = 5;
const float kOccluderMargin = 1e-4;
bool prism_hidden() {
    vec2 size = frame.target.xy, lo = vec2(1e30), hi = vec2(-1e30);
    float nearest = 1.0;
    for (int k = 0; k < 6; ++k) {
        int i = k % 3;
        vec4 c = frame.view_proj * vec4(v_world[i] + normalize(v_n[i]) * params.height * float(k / 3), 1.0);
        if (c.w <= 0.0) return false;
        vec3 ndc = c.xyz / c.w;
        vec2 px = (ndc.xy * 0.5 + 0.5) * size;   // framebuffer pixels (Vulkan: y down, like ndc)
        lo = min(lo, px), hi = max(hi, px);
        nearest = min(nearest, ndc.z);
    }
    if (any(lessThan(hi, vec2(-1.0))) || any(greaterThan(lo, size + 1.0))) return true;   // off screen
    ivec2 t0 = ivec2(clamp(lo - 1.0, vec2(0.0), size - 1.0)) / kTile;
    ivec2 t1 = ivec2(clamp(hi + 1.0, vec2(0.0), size - 1.0)) / kTile;
    if (any(greaterThan(t1 - t0, ivec2(kMaxTiles - 1)))) return false;
    float farthest = 0.0;
    for (int y = t0.y; y <= t1.y; ++y)
        for (int x = t0.x; x <= t1.x; ++x) farthest = max(farthest, texelFetch(occluder_tiles, ivec2(x, y), 0).x);
    return nearest > farthest + kOccluderMargin;
}

// Back-face cull before emitting (for speed; it changes no pixel): the pass culls back faces
// anyway, but only after the geometry shader has written the face's vertices (48 floats each)
// and the rasteriser has set it up. A face is dropped only when it is clearly back-facing (its
// outward normal more than ~0.06 degrees past edge-on, kBackFacing = cos 89.94), so rounding
// can never drop a face the rasteriser would have drawn.
const float kBackFacing = 1e-3;
bool clearly_back(vec3 a, vec3 b, vec3 c) {
    vec3 n = cross(b - a, c - a), v = frame.camera_pos.xyz - a;
    return dot(n, v) < -kBackFacing * length(n) * length(v);
}

void main() {
    // Two passes share this shader, one per tessellation of the torus (preset.toml): only the one
    // that mesh_detail selects emits prisms.
    if (params.mesh_detail != PRISM_MESH) return;
    if (prism_hidden()) return;
    mat2x3 d = triangle_pu_pv(v_world[0], v_world[1], v_world[2], v_uv[0], v_uv[1], v_uv[2]);
    if (dot(d[0], d[0]) == 0.0) return;   // degenerate: no surface, no prism
    vec3 N_f = normalize(cross(v_world[1] - v_world[0], v_world[2] - v_world[0]));
    m = mat3(d[0], d[1], N_f * max(params.height, 1e-5));   // height 0 would make M singular
    m_inv = inverse(m);
    p0 = v_world[0], uv01 = vec4(v_uv[0], v_uv[1]), uv2 = v_uv[2];
    n0 = v_n[0], n1 = v_n[1], n2 = v_n[2];
    vec3 p[3] = vec3[](v_world[0], v_world[1], v_world[2]), q[3];
    for (int i = 0; i < 3; ++i) q[i] = p[i] + normalize(v_n[i]) * params.height;
    // Top, counter-clockwise seen from outside like the triangle.
    if (!clearly_back(q[0], q[1], q[2])) { emit(0, 1.0); emit(1, 1.0); emit(2, 1.0); EndPrimitive(); }
    // Sides: edge i -> j of the counter-clockwise triangle, quad (p_i, p_j, p_j', p_i') faces out;
    // its two triangles as the strips below make them (prism.frag's prism_exit lists the same).
    for (int e = 0; e < 3; ++e) {
        int i = e, j = (e + 1) % 3;
        bool from_i = prism_diagonal_from_i(p[i], p[j]);
        bool back = from_i ? clearly_back(q[i], p[i], q[j]) && clearly_back(p[i], p[j], q[j])
                           : clearly_back(p[i], p[j], q[i]) && clearly_back(p[j], q[j], q[i]);
        if (back) continue;
        if (from_i) { emit(i, 1.0); emit(i, 0.0); emit(j, 1.0); emit(j, 0.0); }
        else { emit(i, 0.0); emit(j, 0.0); emit(i, 1.0); emit(j, 1.0); }
        EndPrimitive();
    }
}
