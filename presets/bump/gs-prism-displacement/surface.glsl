// The colour of the displaced surface at texture coordinates uv with normal n: two-tone tiles
// (darker in the grooves, by the height h) lit by Blinn-Phong (passes/bump/lighting.glsl). Shared
// by the prism pass and the base-mesh reference, so the two can be compared exactly.
#include "bump/lighting.glsl"
const vec3 kTileA = vec3(0.74, 0.58, 0.4), kTileB = vec3(0.45, 0.52, 0.6);   // the two tile colours
const float kGroove = 0.45;      // albedo factor at h = 0 (the grooves)
const float kShininess = 40.0, kSpecular = 0.3;
vec3 surface_color(vec3 n, vec2 uv, float h, vec3 world) {
    vec2 cell = floor(uv * params.tiling * 4.0);
    vec3 tile = mod(cell.x + cell.y, 2.0) < 1.0 ? kTileA : kTileB;
    // pattern = smooth: a continuous colour of uv, for comparing two routes to the same point
    // (a colour step turns a 1e-6 difference in uv into a different colour at pixels that
    // straddle it).
    if (params.pattern == PATTERN_SMOOTH) tile = vec3(0.5) + 0.3 * sin(6.2831853 * vec3(uv * params.tiling, uv.x * params.tiling.x + 0.3));
    vec3 albedo = tile * mix(kGroove, 1.0, h);
    vec3 l = normalize(params.light_dir), v = normalize(frame.camera_pos.xyz - world);
    return bump_blinn_phong(n, l, v, albedo, kShininess, kSpecular);
}
