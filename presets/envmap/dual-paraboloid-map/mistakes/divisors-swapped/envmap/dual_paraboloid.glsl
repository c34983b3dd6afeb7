// Dual-paraboloid mapping (001_fe43b953f362fae7.txt L194-224; Heidrich and Seidel 1998): the
// environment as the orthographic reflections in two parabolic mirrors, one per hemisphere.
// The document prints one map's coordinates (L214-216),
//     s = r_x / (1 - r_z),   t = r_y / (1 - r_z)
// which covers r_z <= 0 (|(s, t)| <= 1 there). Pitfall (docs/catalogue.md): the other map needs
// 1 + r_z and covers r_z >= 0. Layer 0 here is the +z map (1 + r_z), layer 1 the document's -z
// map (1 - r_z). Inverse, with rho^2 = s^2 + t^2:
//     r = (2 s, 2 t, +-(1 - rho^2)) / (1 + rho^2)
// Both maps are stored in world axes, upright: image u = (1 + s) / 2, v = (1 - t) / 2. The
// document's texture matrix P M^-1 (L210-212) takes OpenGL's eye-space R back to the world
// (M^-1) before projecting (P); R computed in world space needs neither.
#ifndef PASSLAB_DUAL_PARABOLOID_GLSL
#define PASSLAB_DUAL_PARABOLOID_GLSL
// (s, t) of direction r in map `layer` (0: +z, 1: -z).
// Towards the opposite pole the denominator goes to 0 (and 0/0 at the pole itself): it is
// clamped to kDpMinDenom, which sends those directions far outside the disc (alpha 0 there).
const float kDpMinDenom = 1e-4;
vec2 dp_coord(vec3 r, int layer) {
    float denom = layer == 0 ? 1.0 - r.z : 1.0 + r.z;
    return r.xy / max(denom, kDpMinDenom);
}

vec2 dp_uv(vec2 st) { return vec2(0.5 + 0.5 * st.x, 0.5 - 0.5 * st.y); }
vec2 dp_st(vec2 uv) { return vec2(2.0 * uv.x - 1.0, 1.0 - 2.0 * uv.y); }

// The unit direction at (s, t) of map `layer`.
vec3 dp_direction(vec2 st, int layer) {
    float rho2 = dot(st, st);
    float z = (1.0 - rho2) * (layer == 0 ? 1.0 : -1.0);
    return vec3(2.0 * st, z) / (1.0 + rho2);
}

// The lookup with "both maps applied, alpha selects the active map" (L218-220). Each map is
// stored premultiplied: (colour, 1) inside its disc, (0, 0) outside, and sampled with a
// transparent-black border. Then (sum of both samples).rgb / (sum of both alphas) is the map
// whose disc contains the direction, and at the rim, where bilinear filtering reaches over
// the disc's edge in both maps, their coverage-weighted mean: no seam if they agree there.
// Returns the colour and the +z map's share in alpha.
vec4 dp_combine(vec4 front, vec4 back) {
    float coverage = max(front.a + back.a, 1e-6);
    return vec4((front.rgb + back.rgb) / coverage, front.a / coverage);
}
// Filtered by the maps' mips where they have them (the level from the fragment's derivatives):
// for what the view shows.
vec4 dp_lookup(sampler2DArray maps, vec3 r) {
    r = normalize(r);
    return dp_combine(texture(maps, vec3(dp_uv(dp_coord(r, 0)), 0.0)),
                      texture(maps, vec3(dp_uv(dp_coord(r, 1)), 1.0)));
}
// At level 0 only: for measurements, whose pixels are not a view's pixels.
vec4 dp_lookup_level0(sampler2DArray maps, vec3 r) {
    r = normalize(r);
    return dp_combine(textureLod(maps, vec3(dp_uv(dp_coord(r, 0)), 0.0), 0.0),
                      textureLod(maps, vec3(dp_uv(dp_coord(r, 1)), 1.0), 0.0));
}
#endif
