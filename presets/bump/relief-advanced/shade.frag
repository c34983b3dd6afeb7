#version 450
// Relief mapping, advanced (passes/bump/relief_curved.glsl; 001_fe43b953f362fae7.txt
// L1027-1038): the eye ray is marched below a quadric fitted to the carrier at the entry point,
// so rays that leave the curved surface before hitting the relief are discarded — a relief
// silhouette — and a second march from the hit towards the light shadows the relief.
// method basic: bump/parallax.glsl's relief_intersect (the tangent plane; presets/bump/
// relief-mapping). Curvatures, in the map's uv units (t = uv * tiling), analytic for the
// generator's sphere: a map step along u covers |P_u| / tiling.x = 2 pi R sin(theta) / tiling.x of
// the surface, whose curvature is 1/R, so k_u = 2 pi sin(theta) / tiling.x, k_v = pi / tiling.y
// (independent of R). The plane has k = 0. params.curvature scales both (0: the tangent plane).
#include "bump/parallax.glsl"
#include "bump/relief_curved.glsl"
#include "bump/lighting.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec2 v_uv;
layout(location = 2) in vec3 v_t;
layout(location = 3) in vec3 v_b;
layout(location = 4) in vec3 v_n;
layout(location = 0) out vec4 hdr;
uniform sampler2D nmap;   // the selected height field (select.frag)
const float kPi = 3.14159265358979;
const float kShadowBias = 0.02;   // depth units: keeps a hit from shadowing itself on slopes
const vec3 kStoneA = vec3(0.62, 0.6, 0.52), kStoneB = vec3(0.5, 0.38, 0.3);   // the two tile stones
const float kGrout = 0.35;       // albedo factor at the bottom of the relief (h = 0)
const float kShininess = 40.0, kSpecular = 0.25;

void main() {
    if (!(VISIBLE)) discard;
    mat3 tbn = mat3(normalize(v_t), normalize(v_b), normalize(v_n));
    vec3 V = normalize(transpose(tbn) * (frame.camera_pos.xyz - v_world));
    vec2 t0 = v_uv * params.tiling;
#if SURFACE == 1
    vec2 kappa = params.curvature * vec2(2.0 * kPi * sin(kPi * v_uv.y) / params.tiling.x, kPi / params.tiling.y);
#else
    vec2 kappa = vec2(0.0);
#endif
    vec4 hit = params.method == METHOD_BASIC ? vec4(relief_intersect(nmap, t0, V, params.depth_scale, params.linear_steps, params.binary_steps), 1.0)
                                             : relief_intersect_curved(nmap, t0, V, params.depth_scale, kappa, params.linear_steps, params.binary_steps);
    if (hit.w == 0.0) discard;   // the ray left the surface: a silhouette
    vec4 texel = texture(nmap, hit.xy);
    vec3 n = normalize(tbn * (texel.xyz * 2.0 - 1.0));
    vec3 l = normalize(params.light_dir), v = normalize(frame.camera_pos.xyz - v_world);
    float s = params.shadows ? relief_shadow(nmap, hit.xy, hit.z, transpose(tbn) * l, params.depth_scale, params.shadow_steps, kShadowBias) : 1.0;
    // Albedo: two stones in a checker of tiles, darker towards the bottom of the relief.
    vec2 cell = floor(hit.xy * 4.0);
    vec3 stone = mod(cell.x + cell.y, 2.0) < 1.0 ? kStoneA : kStoneB;
    vec3 albedo = stone * mix(kGrout, 1.0, texel.a);
    vec2 terms = bump_blinn_phong_terms(n, l, v, kShininess);
    hdr = vec4(bump_combine(albedo, terms.x * s, terms.y * s, kSpecular), 1.0);   // alpha 1: covered (tests)
}
