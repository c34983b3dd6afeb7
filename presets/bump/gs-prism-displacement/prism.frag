#version 450
// Ray casting the height field inside one prism (004_9a40ad89bdfc582a.txt L1048-1053). The eye
// ray enters at this fragment's (u, v, w); its direction in texture space is M^-1 dir_world.
// It stays in the prism while the barycentric coordinates of (u, v) are >= 0 and 0 <= w <= 1:
// the exit s_exit is where the first of them reaches 0 (or w reaches 1). March s over
// [0, s_exit] (linear steps, then bisection) for the first point with w <= h(u, v); none: the
// ray leaves through a side into the neighbouring prism, which shades it from its own side
// face, or out of the shell altogether: discard. The hit's depth is written, so the nearest hit
// among overlapping prisms wins. Normal at the hit: Blinn's N' = N + h_u (N_n x P_v) +
// h_v (P_u x N_n) from the offset map (passes/bump/blinn_bump.glsl), N_n interpolated from the
// vertex normals with the hit's barycentrics.
#include "bump/blinn_bump.glsl"
#include "surface.glsl"
layout(location = 0) in vec3 g_world;
layout(location = 1) in vec3 g_uvw;
layout(location = 2) flat in mat3 g_m;
layout(location = 5) flat in vec3 g_p0;
layout(location = 6) flat in vec4 g_uv01;
layout(location = 7) flat in vec2 g_uv2;
layout(location = 8) flat in vec3 g_n0;
layout(location = 9) flat in vec3 g_n1;
layout(location = 10) flat in vec3 g_n2;
layout(location = 0) out vec4 hdr;
uniform sampler2D offsets;   // (h, h_u, h_v) per unit of the map (bump/offset_map.frag)

float height_at(vec2 uv) { return texture(offsets, uv * params.tiling).x; }

void main() {
    vec3 dir = normalize(g_world - frame.camera_pos.xyz);
    vec3 d = inverse(g_m) * dir;                       // (u, v, w) per world unit along the ray
    vec2 uv0 = g_uv01.xy, uv1 = g_uv01.zw, uv2 = g_uv2;
    mat2 to_bary = inverse(mat2(uv1 - uv0, uv2 - uv0));  // (lambda_1, lambda_2) from uv - uv0
    vec2 b0 = to_bary * (g_uvw.xy - uv0), db = to_bary * d.xy;
    vec3 lam0 = max(vec3(1.0 - b0.x - b0.y, b0), 0.0), dlam = vec3(-db.x - db.y, db);
    // kEdgeEps lets the ray run a hair past the triangle's edges: a ray that meets the floor
    // exactly on an edge shared by two prisms would otherwise be refused by both (rounding),
    // leaving a hole; where both accept it, the depth test keeps one.
    const float kEdgeEps = 1e-3;
    float s_exit = 1e9;
    for (int k = 0; k < 3; ++k)
        if (dlam[k] < 0.0) s_exit = min(s_exit, (lam0[k] + kEdgeEps) / -dlam[k]);
    if (d.z > 0.0) s_exit = min(s_exit, (1.0 - g_uvw.z) / d.z);
    if (d.z < 0.0) s_exit = min(s_exit, -g_uvw.z / d.z);   // the floor w = 0 (h >= 0 hits first)

    // Linear search, then bisection, for the first point at or below the height field. The
    // samples are s_exit * i / n, so the last one is exactly the exit; kFloorEps keeps a ray
    // that leaves through the floor (w = 0 up to rounding) a hit when h = 0.
    const float kFloorEps = 1e-5;
    float step_size = s_exit / float(params.linear_steps), s = 0.0;
    bool found = false;
    for (int i = 0; i <= params.linear_steps; ++i) {
        s = s_exit * float(i) / float(params.linear_steps);
        vec3 p = g_uvw + d * s;
        if (p.z <= height_at(p.xy) + kFloorEps) { found = true; break; }
    }
    if (!found) discard;
    float lo = max(s - step_size, 0.0), hi = s;
    for (int i = 0; i < params.binary_steps; ++i) {
        float mid = 0.5 * (lo + hi);
        vec3 p = g_uvw + d * mid;
        if (p.z <= height_at(p.xy) + kFloorEps) hi = mid; else lo = mid;
    }
    vec3 hit = g_uvw + d * hi;
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
