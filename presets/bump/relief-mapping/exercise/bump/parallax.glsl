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
    return t0 + h_n * (limited ? V.xy : V.xy / max(V.z, 1e-4));
}

// Relief mapping (001 L984-1023): march the eye ray into the height field until it is below the
// surface (linear search, `linear_steps`), then refine between the last two points by bisection
// (`binary_steps`). Depth d = 1 - h goes from 0 at the carrier to 1 at the bottom; the ray
// enters at depth 0 and descends `scale` in uv per unit of depth along -V. Returns (uv, depth).
vec3 relief_intersect(sampler2D height_map, vec2 t0, vec3 V, float scale, int linear_steps, int binary_steps) {
    // EXERCISE (bump/relief-mapping): fill in the three TODO blocks; parallax_uv above is the
    // reference's and is not graded here. As shipped the ray stops where it enters (depth 0).
    //     passlab run   bump/relief-mapping --exercise presets/bump/relief-mapping/exercise
    //     passlab grade bump/relief-mapping --exercise presets/bump/relief-mapping/exercise
    // TODO 1: delta, the uv travelled by the eye ray from the entry point A at depth 0 (the
    // carrier) to the exit point B at depth 1 (001 L988-989). The ray goes INTO the surface,
    // along -V (V: tangent space, unit, from the surface to the eye); one unit of depth is
    // `scale` in uv, and per unit it descends the ray moves |V.xy| / V.z sideways. Guard V.z -> 0.
    vec2 delta = vec2(0.0);
    float step_size = 1.0 / float(linear_steps), d = 0.0;
    // TODO 2: linear search (001 L990): advance d in steps of step_size, at most
    // linear_steps times, and stop at the first point t0 + delta d that is at or below the
    // surface. The map stores HEIGHT h (alpha, 1 = the carrier); the ray's d is a DEPTH, 1 - h.

    // TODO 3: binary search (001 L991): the hit lies between the last point above the
    // surface (d - step_size, but not above 0) and the first one below it (d, but not below 1).
    // Halve that bracket binary_steps times, keeping the half that contains the crossing, and
    // return the uv and depth of its end that is below the surface: vec3(uv, depth).
    return vec3(t0, 0.0);
}
#endif
