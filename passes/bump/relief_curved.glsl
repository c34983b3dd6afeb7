// Relief mapping on a curved carrier, with silhouettes and self-shadowing (001_fe43b953f362fae7.txt
// L1027-1038, "higher-order surface approximation relief mapping: surface approximated with
// polynomials, produces silhouettes ... shadows in relief"; after Oliveira & Policarpo 2005).
//
// bump/parallax.glsl's relief_intersect marches the eye ray below the *tangent plane* at the
// entry point: it never leaves the relief, so the silhouette stays the carrier's. Here the
// carrier is approximated at the entry point by the quadric z = (k_u x^2 + k_v y^2) / 2 (x, y
// along T and B, in the same uv units as the relief depth `scale`; k the surface's normal
// curvatures in those units). A ray point at tangent-plane depth d (in units of `scale`) and
// lateral offset o = delta d lies below the curved carrier by
//     d_rel(d) = d - (k_u o.x^2 + k_v o.y^2) / (2 scale)
// It hits the relief where d_rel >= 1 - h(t0 + o); if d_rel returns to 0 first, the ray has
// left the object through the curved surface: no hit (a silhouette pixel, discarded).
// With k = 0 this is relief_intersect step for step (same linear search, same bisection).
#ifndef PASSLAB_RELIEF_CURVED_GLSL
#define PASSLAB_RELIEF_CURVED_GLSL

float relief_depth_below_carrier(float d, vec2 delta, vec2 kappa, float scale) {
    vec2 o = delta * d;
    return d - dot(kappa, o * o) / (2.0 * scale);
}

// Returns (uv, d_rel at the hit, 1 if hit else 0).
vec4 relief_intersect_curved(sampler2D height_map, vec2 t0, vec3 V, float scale, vec2 kappa, int linear_steps, int binary_steps) {
    vec2 delta = -V.xy / max(V.z, 1e-4) * scale;   // uv per unit of tangent-plane depth
    // The search interval: up to the floor (d_rel = 1) if the ray reaches it, else up to where
    // it leaves the carrier (d_rel = 0 again). With c = (k_u delta.x^2 + k_v delta.y^2)/(2 scale),
    // d_rel = d - c d^2: exit at d = 1/c; floor at the first root of c d^2 - d + 1 = 0.
    float c = max(dot(kappa, delta * delta) / (2.0 * scale), 0.0);
    float d_end = 1.0;
    if (c > 0.0) {
        if (4.0 * c <= 1.0) d_end = (1.0 - sqrt(1.0 - 4.0 * c)) / (2.0 * c);   // reaches the floor
        else d_end = 1.0 / c;                                                    // never gets that deep
    }
    float step_size = d_end / float(linear_steps), d = 0.0;
    bool found = false;
    for (int i = 0; i < linear_steps; ++i) {
        if (relief_depth_below_carrier(d, delta, kappa, scale) >= 1.0 - texture(height_map, t0 + delta * d).a) { found = true; break; }
        d += step_size;
    }
    // The last sample, at d_end: on the floor (hit) or back at the carrier (checked, else a miss).
    // (Flat carrier, c = 0: nothing here, d stays where the search left it, as in relief_intersect.)
    if (!found && c > 0.0) {
        d = d_end;
        found = relief_depth_below_carrier(d, delta, kappa, scale) >= 1.0 - texture(height_map, t0 + delta * d).a;
        if (!found) return vec4(t0, 0.0, 0.0);   // (on the floor branch d_rel(d_end) = 1: always found)
    }
    float lo = max(d - step_size, 0.0), hi = min(d, d_end);
    for (int i = 0; i < binary_steps; ++i) {
        float mid = 0.5 * (lo + hi);
        if (relief_depth_below_carrier(mid, delta, kappa, scale) >= 1.0 - texture(height_map, t0 + delta * mid).a) hi = mid; else lo = mid;
    }
    return vec4(t0 + delta * hi, relief_depth_below_carrier(hi, delta, kappa, scale), 1.0);
}

// Shadows in relief: march from the hit (uv t, depth d_hit) towards the light L (tangent space,
// L.z > 0) up to the carrier; the point is shadowed if the height field rises above the ray
// anywhere on the way (the ray's depth exceeds 1 - h there by more than `bias`). Locally flat:
// the curvature is ignored over the short way up. Returns 1 lit, 0 shadowed.
float relief_shadow(sampler2D height_map, vec2 t, float d_hit, vec3 L, float scale, int steps, float bias) {
    if (L.z <= 0.0) return 0.0;
    vec2 delta = L.xy / L.z * scale;   // uv per unit of depth climbed
    for (int i = 1; i <= steps; ++i) {
        float climb = d_hit * float(i) / float(steps);
        float d = d_hit - climb;
        if (d > 1.0 - texture(height_map, t + delta * climb).a + bias) return 0.0;
    }
    return 1.0;
}
#endif
