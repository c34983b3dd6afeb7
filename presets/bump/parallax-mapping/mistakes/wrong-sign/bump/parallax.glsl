// Parallax and relief mapping in tangent space (001_fe43b953f362fae7.txt L494-546, L939-1023;
// 000_c9f7e5de708ecbb3.txt L2602-2635). V is the tangent-space direction from the surface to
// the eye (V.z > 0 on the front side); heights h in [0, 1] are read from the normal map's alpha
// (1 = the carrier surface, 0 = the deepest point).
#ifndef PASSLAB_PARALLAX_GLSL
#define PASSLAB_PARALLAX_GLSL

// Parallax mapping (001 L506-532): the height is assumed locally constant; rescale it around
// the carrier, h_n = h s - 0.5 s (s ~ 0.01 in 001), and follow the eye ray to that height:
//     T_n = T_0 + h_n V.xy / V.z
// The offset grows without bound as V.z -> 0 (grazing views). Offset-limited (L536-546) drops
// the division: T_n = T_0 + h_n V.xy, |T_n - T_0| <= 0.5 s.
vec2 parallax_uv(sampler2D height_map, vec2 t0, vec3 V, float s, bool limited) {
    float h_n = texture(height_map, t0).a * s - 0.5 * s;
    return t0 - h_n * (limited ? V.xy : V.xy / max(V.z, 1e-4));
}

// Relief mapping (001 L984-1023): march the eye ray into the height field until it is below the
// surface (linear search, `linear_steps`), then refine between the last two points by bisection
// (`binary_steps`). Depth d = 1 - h goes from 0 at the carrier to 1 at the bottom; the ray
// enters at depth 0 and descends `scale` in uv per unit of depth along -V. Returns (uv, depth).
vec3 relief_intersect(sampler2D height_map, vec2 t0, vec3 V, float scale, int linear_steps, int binary_steps) {
    vec2 delta = -V.xy / max(V.z, 1e-4) * scale;  // uv travelled from depth 0 to depth 1
    float step_size = 1.0 / float(linear_steps), d = 0.0;
    // Linear search: the first sample point at or below the surface.
    for (int i = 0; i < linear_steps; ++i) {
        if (d >= 1.0 - texture(height_map, t0 + delta * d).a) break;
        d += step_size;
    }
    // Binary search between d - step and d.
    float lo = max(d - step_size, 0.0), hi = min(d, 1.0);
    for (int i = 0; i < binary_steps; ++i) {
        float mid = 0.5 * (lo + hi);
        if (mid >= 1.0 - texture(height_map, t0 + delta * mid).a) hi = mid; else lo = mid;
    }
    return vec3(t0 + delta * hi, hi);
}
#endif
