#version 450
// Per-fragment reconstruction (002_644d46bdce7e5305.txt L2740-2747): one tap of the RH volume
// (the engine's choice, L2742, instead of the original four rotating taps) half a cell
// above the surface, integrated over the surface-aligned hemisphere in the SH domain; plus the
// direct light of the spot with the RSM as its shadow map.
//   radiance = rho/pi * E_direct * V + rho * E_indirect / pi
// Targets: `radiance` (linear, direct + indirect: what gi_compare.sh compares), `indirect`
// (E_indirect / pi, before the albedo: the uniform-field cases), `radiance_first` (the same
// from the first-bounce grid alone, with params.verify: the bounces = 1 case), `coverage`, and
// `test_field` (with params.verify): the uniform test field's own E / pi at the tap point,
// uniform_L + uniform_ramp . p_tap (isotropic, so E / pi = L), written from its closed form and
// not from the grid: what the reconstruction across the cascades must give; alpha 1 where the
// tap lies within the outermost hint centres.
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in vec3 v_albedo;
layout(location = 0) out vec4 radiance;
layout(location = 1) out vec4 indirect;
layout(location = 2) out vec4 coverage;
#if VERIFY_TARGETS
// The test-only targets, in their own pipeline (params.verify): two rgba32f writes per fragment
// are a third of this pass's cost on a CPU rasteriser.
layout(location = 3) out vec4 radiance_first;
layout(location = 4) out vec4 test_field;
#endif
uniform sampler3D rh;
uniform sampler3D rh_first;
uniform sampler2D rsm_pos;
#ifndef VERIFY_TARGETS
#define VERIFY_TARGETS 0
#endif
#include "gi/cornell.glsl"
#include "gi/rh_grid.glsl"

// 3x3 PCF on the RSM's distance-to-light channel.
float visibility(vec3 p, vec3 n) {
    p += 0.015 * n;  // normal offset: the RSM texels are ~1 cm wide at the floor, ~2x at the walls
    vec4 clip = cameras.light.view_proj * vec4(p, 1.0);
    if (clip.w <= 0.0) return 0.0;
    vec2 uv = clip.xy / clip.w * 0.5 + 0.5;
    float dist = length(p - CORNELL_LIGHT_POS);
    vec2 texel = 1.0 / vec2(textureSize(rsm_pos, 0));
    // slope-scaled: a texel spans ~ its width * tan(theta) in distance on a surface at theta
    float cos_t = clamp(abs(dot(n, normalize(CORNELL_LIGHT_POS - p))), 0.05, 1.0);
    float bias = 0.005 + min(0.1, 0.03 * sqrt(1.0 - cos_t * cos_t) / cos_t);
    float lit = 0.0;
    for (int i = -1; i <= 1; ++i)
        for (int j = -1; j <= 1; ++j) lit += dist <= textureLod(rsm_pos, uv + vec2(i, j) * texel, 0.0).w + bias ? 1.0 : 0.0;
    return lit / 9.0;
}

vec3 indirect_over_pi(sampler3D grid, vec3 p, vec3 n) {
    vec4 r, g, b;
    rh_sample(grid, p + RH_TAP_OFFSET * n, r, g, b);
    return max(vec3(rh_irradiance_over_pi(r, n), rh_irradiance_over_pi(g, n), rh_irradiance_over_pi(b, n)), vec3(0.0));
}

void main() {
    vec3 n = normalize(v_normal);
    if (dot(n, frame.camera_pos.xyz - v_world) < 0.0) n = -n;  // two-sided walls
    vec3 rho = v_albedo;
    vec3 direct = params.direct ? rho / SH_PI * cornell_light_irradiance(v_world, n) * visibility(v_world, n) : vec3(0.0);
    vec3 e = indirect_over_pi(rh, v_world, n);
    radiance = vec4(direct + rho * e, 1.0);
    indirect = vec4(e, 1.0);
    coverage = vec4(1.0);
#if VERIFY_TARGETS
    radiance_first = vec4(direct + rho * indirect_over_pi(rh_first, v_world, n), 1.0);
    {
        // alpha: the tap point lies within the outermost hint centres, where no cascade clamps
        // (nearer a wall the lookup holds the value at the clamped point, by design)
        vec3 tap = v_world + RH_TAP_OFFSET * n;
        bool inside = all(lessThanEqual(abs(tap), vec3(RH_HI - 0.5 * RH_CELL)));
        test_field = vec4(vec3(params.uniform_L + dot(params.uniform_ramp, tap)), inside ? 1.0 : 0.0);
    }
#endif
}
