#version 450
// Bounces 2..N (002_644d46bdce7e5305.txt L2694-2722): every RH samples the radiance field around
// it. For each sample direction d at distance r: interpolate the SH at q = x + r d (trilinear),
// integrate it over the hemisphere aligned with -d ("reflected" radiance on an imaginary surface
// at q facing x, albedo params.bounce_albedo), and add that radiance, arriving from d, to x's SH.
// Samples are not equally reliable (L2713): RHs near surfaces are, so each is weighted by
// the sampled RH's minimum RSM distance r_min, and attenuated by a probabilistic occlusion from
// its r_min and r_max (L2715-2721):
//   factor = 1 - clamp((r - r_min) / (r_max - r_min), 0, 1)
//   weight = clamp(1 - r_min / R, 0, 1)          (distances in units of the gather radius R)
// The printed snippet (L2720) divides by (lMinimumDistance - lMinimumDistance), which is 0: use
// (r_max - r_min), kept away from 0 for an RH whose samples were all at one distance.
// The estimate c_k = 4 pi sum_j weight_j factor_j L_j y_k(d_j) / sum_j weight_j, and the grid
// after this bounce is the first bounce plus it: T_{b+1} = L_1 + G(T_b), so N - 1 passes sum
// the series L_1 + G L_1 + ... + G^{N-1} L_1.
// The sample pattern is the same for every RH (16 Fibonacci directions and their antipodes,
// pair j at r_j = (j + 0.5) R / 16): a uniform field stays uniform and isotropic. Each cascade
// exchanges light within itself (gi/rh_grid.glsl): a sample beyond its border reads its
// outermost hints, as the cascades of the engine are separate volumes; one lookup per sample
// where reading the blended field would cost two in every fade band.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
uniform sampler3D rh;         // T_b (linear filter)
uniform sampler3D rh_dist;    // r_min, r_max (nearest)
layout(rgba32f) readonly uniform image3D rh_first;   // L_1
layout(rgba32f) writeonly uniform image3D rh_next;   // T_{b+1}
#include "gi/rh_grid.glsl"

const int PAIRS = 16;

vec3 fibonacci_hemisphere(int j) {
    float z = 1.0 - (float(j) + 0.5) / float(PAIRS);  // cos theta in (0, 1)
    float r = sqrt(max(0.0, 1.0 - z * z)), phi = 2.39996323 * float(j);
    return vec3(r * cos(phi), z, r * sin(phi));
}

void main() {
    if (!rh_exchange_runs()) return;  // cached, or a frame between updates: rh_next is not read (gi/rh_copy.comp)
    ivec3 g = ivec3(gl_GlobalInvocationID);
    int k = g.z / RH_N;  // the cascade (gi/rh_grid.glsl)
    ivec3 c = ivec3(g.xy, g.z % RH_N);
    if (any(greaterThanEqual(c, ivec3(RH_N))) || k >= RH_CASCADES_MAX) return;
    if (k >= rh_cascades()) {  // an unused cascade stays zero (see gi/rh_inject.comp)
        for (int ch = 0; ch < 3; ++ch) imageStore(rh_next, rh_texel(k, ch, c), vec4(0.0));
        return;
    }
    vec3 x = rh_cell_center(k, c);
    float R = params.gather_radius;
    vec4 sr = vec4(0.0), sg = vec4(0.0), sb = vec4(0.0);
    float wsum = 0.0;
    for (int j = 0; j < 2 * PAIRS; ++j) {
        vec3 d = j < PAIRS ? fibonacci_hemisphere(j) : -fibonacci_hemisphere(j - PAIRS);
        float r = (float(j % PAIRS) + 0.5) * R / float(PAIRS);
        vec3 q = x + r * d;
        vec4 qr, qg, qb;
        rh_sample_cascade(rh, k, q, qr, qg, qb);
        vec2 mm = rh_distances(rh_dist, k, q);
        float rmin = mm.x, rmax = mm.y;
        // TODO 1 (002_644d46bdce7e5305.txt L2713-2721): the sampled hint's reliability and the
        // occlusion heuristic from its minimum and maximum RSM sample distances:
        //   factor = 1 - clamp((r - r_min) / (r_max - r_min), 0, 1)
        //   weight = clamp(1 - r_min / R, 0, 1)
        // Careful: the printed snippet (L2720) divides by (lMinimumDistance - lMinimumDistance).
        // Keep the divisor away from 0 for a hint whose samples were all at one distance.
        float factor = 0.0;
        float weight = 0.0;
        vec3 L = params.bounce_albedo * max(vec3(rh_irradiance_over_pi(qr, -d), rh_irradiance_over_pi(qg, -d), rh_irradiance_over_pi(qb, -d)), vec3(0.0));
        vec4 y = rh_basis(d) * (weight * factor);
        sr += L.r * y;
        sg += L.g * y;
        sb += L.b * y;
        wsum += weight;
    }
    float norm = wsum > 0.0 ? 4.0 * SH_PI / wsum : 0.0;
    for (int ch = 0; ch < 3; ++ch) {
        ivec3 t = rh_texel(k, ch, c);
        vec4 s = ch == 0 ? sr : ch == 1 ? sg : sb;
        // TODO 2: the grid after this bounce is the first bounce plus the gathered field,
        //   T_{b+1} = L_1 + G(T_b)    (L_1 = imageLoad(rh_first, t), G(T_b) = s * norm)
        imageStore(rh_next, t, s * norm);
    }
}
