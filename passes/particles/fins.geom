#version 450
// Fins (004_9a40ad89bdfc582a.txt L1077-1104): "add fins at the silhouette — a polygon standing on
// the edge between 2 silhouette polygons", generated in the geometry shader, which "checks whether
// or not the polygon has a silhouette edge: silhouette <=> e.n1 > 0 and e.n2 < 0, e = eye vector,
// from edge to eye" (L1098-1101).
//
// Input: triangles with adjacency (vertices 0, 2, 4 the triangle; 1, 3, 5 the vertex across each
// edge). The seed's question (L1104), "do we need to check the other orientation of signs?":
// no — testing only from the front-facing triangle (n1 towards the eye) finds each silhouette
// edge exactly once; the triangle on the other side sees e.n1 < 0 and emits nothing. Testing
// both orientations would stand every fin twice on its edge. The seed's GS also passes the input
// triangle through; here the skin and shells are drawn by their own passes, so it emits fins only.
// Every fin is counted in `fins.emitted`.
layout(triangles_adjacency) in;
layout(triangle_strip, max_vertices = 12) out;
#include "npr/silhouette.glsl"
layout(location = 0) in vec3 v_world[];
layout(location = 1) in vec3 v_normal[];
layout(location = 2) in vec2 v_uv[];
layout(location = 0) out vec2 fin_st;      // (along the edge in strand cells, height 0..1)
layout(location = 1) out vec3 fin_normal;
layout(std430) buffer Fins { uint emitted; } fins;

void emit_fin(int ia, int ib) {
    vec3 a = v_world[ia], b = v_world[ib];
    float cells = length(b - a) * params.fin_cells;
    vec3 na = normalize(v_normal[ia]), nb = normalize(v_normal[ib]);
    vec3 n = normalize(na + nb);
    vec3 p[4] = vec3[](a, b, a + na * params.fur_length, b + nb * params.fur_length);
    vec2 st[4] = vec2[](vec2(0, 0), vec2(cells, 0), vec2(0, 1), vec2(cells, 1));
    for (int k = 0; k < 4; ++k) {
        fin_st = st[k];
        fin_normal = n;
        gl_Position = frame.view_proj * vec4(p[k], 1.0);
        EmitVertex();
    }
    EndPrimitive();
    atomicAdd(fins.emitted, 1u);
}

void main() {
    vec3 p[6];
    for (int i = 0; i < 6; ++i) p[i] = v_world[i];
    if (!faces_eye(p[0], p[2], p[4], 0.0)) return;          // e.n1 > 0 only
    for (int e = 0; e < 3; ++e) {
        int ia = 2 * e, ib = (2 * e + 2) % 6;
        vec3 a = p[ia], o = p[2 * e + 1], b = p[ib], own = p[(2 * e + 4) % 6];
        if (o == own) continue;                             // an open border: no triangle across
        if (!faces_eye(b, a, o, 0.0)) emit_fin(ia, ib);     // e.n2 <= 0: the edge is a silhouette
    }
}
