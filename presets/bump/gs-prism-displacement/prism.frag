#version 450
// Ray casting the height field inside one prism (004_9a40ad89bdfc582a.txt L1048-1052). The
// eye ray enters the prism at this fragment (its world position, taken into the prism's
// (u, v, w) by M^-1); its direction there is M^-1 dir_world. It leaves the prism where it
// passes outwards through one of its faces (prism_exit: ray-triangle tests against the base,
// the lifted top and the six side triangles). March s over [0, s_exit] (linear steps, bisection,
// a secant step) for the first point with w <= h(u, v); none: the ray goes on into the neighbouring
// prism, which shades it from its own side face, or out of the shell altogether: discard. The
// hit's depth is written, so the nearest hit wins where several prisms' fragments cover a
// pixel. Normal at the hit: Blinn's N' = N + h_u (N_n x P_v) + h_v (P_u x N_n) from the offset
// map (passes/bump/blinn_bump.glsl), N_n interpolated from the vertex normals with the hit's
// barycentrics.
#include "bump/blinn_bump.glsl"
#include "surface.glsl"
#include "prism_faces.glsl"
layout(location = 0) in vec3 g_world;
layout(location = 1) in vec3 g_uvw;
layout(location = 2) flat in mat3 g_m;
layout(location = 5) flat in vec3 g_p0;
layout(location = 6) flat in vec4 g_uv01;
layout(location = 7) flat in vec2 g_uv2;
layout(location = 8) flat in vec3 g_n0;
layout(location = 9) flat in vec3 g_n1;
layout(location = 10) flat in vec3 g_n2;
layout(location = 11) flat in vec3 g_p1;
layout(location = 12) flat in vec3 g_p2;
layout(location = 0) out vec4 hdr;
uniform sampler2D offsets;      // (h, h_u, h_v) per unit of the map (bump/offset_map.frag)
uniform sampler2D height_map;   // its h alone (select.frag): the march's lookups, one channel
layout(location = 13) flat in mat3 g_m_inv;   // M^-1, once per prism (prism.geom), locations 13-15

float height_at(vec2 uv) { return texture(height_map, uv * params.tiling).x; }

// Ray o + t dir against triangle (a, b, c) (Moller-Trumbore); t, or 1e9 if missed. `margin`
// (barycentric) widens the triangle a little, so a ray through an edge between two faces of
// the prism meets at least one of them (1e-4 for the faces).
float ray_triangle_margin(vec3 o, vec3 dir, vec3 a, vec3 b, vec3 c, float margin) {
    vec3 e1 = b - a, e2 = c - a, pv = cross(dir, e2);
    float det = dot(e1, pv);
    if (abs(det) < 1e-12) return 1e9;
    vec3 tv = o - a;
    float bu = dot(tv, pv) / det;
    vec3 qv = cross(tv, e1);
    float bv = dot(dir, qv) / det, t = dot(e2, qv) / det;
    return (bu >= -margin && bv >= -margin && bu + bv <= 1.0 + margin) ? t : 1e9;
}
float ray_triangle(vec3 o, vec3 dir, vec3 a, vec3 b, vec3 c) { return ray_triangle_margin(o, dir, a, b, c, 1e-4); }

// Where the ray leaves this prism: the nearest face it passes *outwards* through, among the
// base triangle, the top (corners lifted along the vertex normals) and the six side triangles.
// Faces it enters by (the one this fragment lies on) are skipped by the direction test, not by
// distance, so rounding at t ~ 0 cannot end the march before it starts.
float leave(vec3 o, vec3 dir, vec3 a, vec3 b, vec3 c, float outward) {
    vec3 n = cross(b - a, c - a) * outward;   // outward = -1 for the base (it faces into the prism)
    float t = dot(n, dir) > 0.0 ? ray_triangle(o, dir, a, b, c) : 1e9;
    return t > -1e-6 ? max(t, 0.0) : 1e9;   // a face behind the entry point is not the exit
}
bool g_exit_base;   // set by prism_exit: the ray leaves through the base triangle
// kBaseMargin widens the base triangle (barycentric units) for rays that leave through a side
// face just above the bottom edge (w < kNearBottom): they meet the base plane right beyond the
// edge, and are taken as hitting it there. Without this a ray that reaches the base on an edge
// shared by two prisms can be refused by both: it leaves the first through a side a hair above
// the edge, and the second's side face is too thin there for the rasteriser (subpixel
// precision) to give it a fragment.
const float kBaseMargin = 1e-3, kNearBottom = 1e-2;
float prism_exit(vec3 o, vec3 dir, vec3 entry, vec3 d) {
    vec3 p[3] = vec3[](g_p0, g_p1, g_p2);
    vec3 n[3] = vec3[](g_n0, g_n1, g_n2);
    vec3 q[3];
    for (int i = 0; i < 3; ++i) q[i] = p[i] + normalize(n[i]) * params.height;
    float best = leave(o, dir, q[0], q[1], q[2], 1.0);
    for (int e = 0; e < 3; ++e) {
        int i = e, j = (e + 1) % 3;
        // The quad's two triangles, split along p_i - q_j or p_j - q_i as prism.geom draws it
        // (chosen by select, not by a branch: on lavapipe both sides of a branch run).
        bool from_i = prism_diagonal_from_i(p[i], p[j]);
        vec3 a1 = from_i ? q[i] : p[i], b1 = from_i ? p[i] : p[j], c1 = from_i ? q[j] : q[i];
        vec3 a2 = from_i ? p[i] : p[j], b2 = from_i ? p[j] : q[j], c2 = from_i ? q[j] : q[i];
        best = min(best, min(leave(o, dir, a1, b1, c1, 1.0), leave(o, dir, a2, b2, c2, 1.0)));
    }
    float base = -dot(cross(p[1] - p[0], p[2] - p[0]), dir) > 0.0 ? ray_triangle_margin(o, dir, p[0], p[1], p[2], kBaseMargin) : 1e9;
    base = base > -1e-6 ? max(base, 0.0) : 1e9;
    g_exit_base = base < 1e8 && (base <= best || (entry + d * best).z < kNearBottom);
    return g_exit_base ? base : best;
}

void main() {
    vec3 dir = normalize(g_world - frame.camera_pos.xyz);
    vec3 d = g_m_inv * dir;                       // (u, v, w) per world unit along the ray
    vec2 uv0 = g_uv01.xy, uv1 = g_uv01.zw, uv2 = g_uv2;
    mat2 to_bary = inverse(mat2(uv1 - uv0, uv2 - uv0));  // (lambda_1, lambda_2) from uv - uv0
    // The entry point in the prism's (u, v, w): this fragment's world position through M^-1
    // (the faces are lifted along vertex normals, so their own uvw would not match M exactly).
    vec3 entry = g_m_inv * (g_world - g_p0) + vec3(uv0, 0.0);
    // The ray runs to where it leaves the prism's geometry (world distance = s, as |dir| = 1).
    float s_exit = prism_exit(g_world, dir, entry, d);
    if (s_exit > 1e8) discard;   // grazing a face: no interior to march
    // Linear search, then bisection, then one secant step, for the first point at or below the
    // height field. The samples are s_exit * i / n, so the last one is exactly the exit; a ray
    // that leaves through the base triangle has reached w = 0 <= h there: a hit by definition
    // (its w is 0 only up to the rounding of the face intersection, so it is not left to the
    // test). gap = w - h(u, v) along the ray: > 0 above the relief, <= 0 at or below it.
    float step_size = s_exit / float(params.linear_steps), s = 0.0;
    float gap = 1.0, gap_before = 1.0;
    bool found = false;
    for (int i = 0; i <= params.linear_steps; ++i) {
        s = s_exit * float(i) / float(params.linear_steps);
        vec3 p = entry + d * s;
        gap_before = gap;
        gap = p.z - height_at(p.xy);
        if (gap <= 0.0 || (i == params.linear_steps && g_exit_base)) { found = true; break; }
    }
    if (!found) discard;
    // The crossing lies in [lo, hi]: lo above the relief (gap_lo > 0), hi at or below it.
    float lo = max(s - step_size, 0.0), hi = s, gap_lo = gap_before, gap_hi = gap;
    for (int i = 0; i < params.binary_steps; ++i) {
        float mid = 0.5 * (lo + hi);
        vec3 p = entry + d * mid;
        float g = p.z - height_at(p.xy);
        if (g <= 0.0) { hi = mid; gap_hi = g; } else { lo = mid; gap_lo = g; }
    }
    // Secant step (parallax occlusion mapping's refinement): where the straight line through
    // (lo, gap_lo) and (hi, gap_hi) crosses gap = 0. Exact where w - h is linear along the ray
    // over the bracket (a planar height field: every step is; case secant-exact-on-a-ramp), and
    // for the bevelled tiles as good as two more bisection steps at no lookup (README,
    // Performance). Skipped when the bracket has no sign change: the first sample is already
    // below (s = 0), or the forced hit at the base exit.
    if (s > 0.0 && gap_lo > 0.0 && gap_hi <= 0.0) hi = mix(lo, hi, gap_lo / (gap_lo - gap_hi));
    vec3 hit = entry + d * hi;
    vec3 world = g_p0 + g_m * (hit - vec3(uv0, 0.0));
    vec4 clip = frame.view_proj * vec4(world, 1.0);
    gl_FragDepth = clip.z / clip.w;

    vec2 bh = to_bary * (hit.xy - uv0);
    vec3 N_n = normalize((1.0 - bh.x - bh.y) * g_n0 + bh.x * g_n1 + bh.y * g_n2);
    vec4 o = texture(offsets, hit.xy * params.tiling);
    vec3 n = normalize(blinn_bump_normal(N_n, g_m[0], g_m[1], params.height * o.y * params.tiling.x, params.height * o.z * params.tiling.y));
    hdr = vec4(surface_color(n, hit.xy, o.x, world), 1.0);
    // show = prisms: red where the ray entered through a prism top, blue through a side; green = hit w.
    if (params.show == SHOW_PRISMS) hdr = vec4(g_uvw.z > 0.999 ? 0.9 : 0.1, hit.z, g_uvw.z > 0.999 ? 0.1 : 0.9, 1.0);
}
