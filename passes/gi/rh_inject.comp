#version 450
// First bounce (002_644d46bdce7e5305.txt L2667-2692): every RH samples the RSM stochastically
// and encodes the radiance it receives as 2-band SH (L2679). n^2 samples per RH and frame
// (n = params.rsm_samples), one per stratum of the RSM (a random texel inside each of n x n
// blocks), each at a random point of the RH's cell ("a uniform distribution of sample points in a Radiance Hint
// cell", L2673). A sample is a VPL with flux phi (the block's flux: texel flux x block
// texels), normal n_s, at p_s; towards the point x it radiates I = (phi / pi) max(n_s . w, 0),
// w = (x - p_s) / d, which arrives at x from direction -w with irradiance I / d^2 (d clamped
// to one of its cascade's cells: the 1/d^2 singularity of a point light). Its SH coefficients:
//   c_k += (I / d^2) y_k(-w).
// The RH also records the minimum and maximum distance d to its contributing samples (L2692),
// which the bounces use as an occlusion heuristic.
// Cached over frames ("temporal volume caching", L2597, L2762-2764): each frame draws a new
// set of random texels and points (seeded by frame.accum_frame) and the grid keeps the running
// mean c = c_prev + (c_new - c_prev) / (accum_frame + 1), min and max over the frames; it
// restarts by itself when a param changes (accum_frame = 0). A frame costs n^2 samples
// per RH, the picture converges to the mean over all frames.
// params.inject = "uniform" writes the field of radiance uniform_L + uniform_ramp . x +
// uniform_Ly w.y instead (x the hint's centre: with uniform_ramp = 0 the same in every hint) with
// r_min = 0, r_max = params.gather_radius: the test fields. One thread per hint of every cascade
// (gi/rh_grid.glsl): z / RH_N is the cascade.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;
uniform sampler2D rsm_flux;
uniform sampler2D rsm_normal;
uniform sampler2D rsm_pos;
layout(rgba32f) writeonly uniform image3D rh_first;
layout(rg32f) writeonly uniform image3D rh_dist;
uniform sampler3D rh_first_prev;
uniform sampler3D rh_dist_prev;
#include "gi/rh_grid.glsl"
#include "common/hash.glsl"

void main() {
    ivec3 g = ivec3(gl_GlobalInvocationID);
    int k = g.z / RH_N;
    ivec3 c = ivec3(g.xy, g.z % RH_N);
    if (any(greaterThanEqual(c, ivec3(RH_N))) || k >= RH_CASCADES_MAX) return;
    if (k >= rh_cascades()) {
        // An unused cascade holds zeros, not what the memory held: its texels border the last
        // used slab, and a linear filter at that slab's outermost hint centre still reads them
        // with weight 0, and 0 x NaN is NaN.
        for (int ch = 0; ch < 3; ++ch) imageStore(rh_first, rh_texel(k, ch, c), vec4(0.0));
        imageStore(rh_dist, rh_dist_texel(k, c), vec4(0.0));
        return;
    }
    // Cached (L2597, "temporal volume caching"): after params.rh_frames frames since the last
    // change the mean is kept as it is, and the passes after this one are skipped too
    // (gi/rh_copy.comp, gi/rh_bounce.comp), so a still view costs only its shading.
    if (rh_cached()) {
        for (int ch = 0; ch < 3; ++ch) imageStore(rh_first, rh_texel(k, ch, c), texelFetch(rh_first_prev, rh_texel(k, ch, c), 0));
        imageStore(rh_dist, rh_dist_texel(k, c), texelFetch(rh_dist_prev, rh_dist_texel(k, c), 0));
        return;
    }
    // The outermost cascade draws the random numbers a single cascade would (seed offset 0).
    int seed = 2048 * (rh_cascades() - 1 - k);
    float cell = rh_cell(k);
    vec4 cr = vec4(0.0), cg = vec4(0.0), cb = vec4(0.0);
    float rmin = 1e30, rmax = 0.0;
    if (params.inject == INJECT_UNIFORM) {
        // L(w) = uniform_L + uniform_Ly w.y: y_0 = 1 / (2 sqrt(pi)) and y_1^0 = sqrt(3 / (4 pi)) w.y,
        // so c_0 = 2 sqrt(pi) L and c_10 = sqrt(4 pi / 3) L_y.
        float L = params.uniform_L + dot(params.uniform_ramp, rh_cell_center(k, c));
        vec4 cu = vec4(2.0 * sqrt(SH_PI) * L, 0.0, sqrt(4.0 * SH_PI / 3.0) * params.uniform_Ly, 0.0);
        cr = cg = cb = cu;
        rmin = 0.0;
        rmax = params.gather_radius;
    } else {
        ivec2 size = textureSize(rsm_flux, 0);
        int ns = params.rsm_samples;
        ivec2 block = size / ns;
        float texels = float(block.x * block.y);
        for (int a = 0; a < ns; ++a)
            for (int b = 0; b < ns; ++b) {
                vec3 h = hash_pcg3(vec3(c.x * 64 + a + seed, c.y * 64 + b, c.z + 16 * int(frame.accum_frame)));
                ivec2 t = ivec2(a, b) * block + min(ivec2(h.xy * vec2(block)), block - 1);
                vec3 phi = texelFetch(rsm_flux, t, 0).rgb * texels;
                if (dot(phi, vec3(1.0)) <= 0.0) continue;
                vec3 ps = texelFetch(rsm_pos, t, 0).xyz, ns_ = texelFetch(rsm_normal, t, 0).xyz;
                vec3 x = rh_cell_center(k, c) + (hash_pcg3(vec3(c.x * 64 + a + 17 + seed, c.y * 64 + b + 31, c.z + 7 + 16 * int(frame.accum_frame))) - 0.5) * cell;
                vec3 v = x - ps;
                float d = length(v);
                vec3 w = v / max(d, 1e-6);
                float facing = max(dot(ns_, w), 0.0);
                if (facing <= 0.0) continue;
                float dc = max(d, cell);
                vec3 e = phi / SH_PI * facing / (dc * dc);
                vec4 y = rh_basis(-w);
                cr += e.r * y;
                cg += e.g * y;
                cb += e.b * y;
                rmin = min(rmin, d);
                rmax = max(rmax, d);
            }
        // the running mean over frames (and the extremes over them)
        uint n_prev = frame.accum_frame;
        if (n_prev > 0u) {
            float f = 1.0 / float(n_prev + 1u);
            cr = mix(texelFetch(rh_first_prev, rh_texel(k, 0, c), 0), cr, f);
            cg = mix(texelFetch(rh_first_prev, rh_texel(k, 1, c), 0), cg, f);
            cb = mix(texelFetch(rh_first_prev, rh_texel(k, 2, c), 0), cb, f);
            vec2 mm = texelFetch(rh_dist_prev, rh_dist_texel(k, c), 0).xy;
            if (mm.y > 0.0) { rmin = min(rmin, mm.x); rmax = max(rmax, mm.y); }
        }
        if (rmax == 0.0) rmin = 0.0;
    }
    imageStore(rh_first, rh_texel(k, 0, c), cr);
    imageStore(rh_first, rh_texel(k, 1, c), cg);
    imageStore(rh_first, rh_texel(k, 2, c), cb);
    imageStore(rh_dist, rh_dist_texel(k, c), vec4(rmin, rmax, 0.0, 0.0));
}
