// Non-parametric sampling (Efros and Leung 1999; 003_cfc3b5b225ddab3d.txt L35-47): "given the
// NxN neighbourhood w(p) around an unknown pixel p: 1. find the patches of the source similar to
// it, 2. their centre pixels are candidates for p, 3. sample one at random, weighted by the
// distance d". Shared by texture-synthesis (grow an image from a seed) and image-completion
// (fill a hole from its border inwards).
//
// The includer defines, before including this file:
//   vec4 el_canvas(ivec2 p)  the image being built: rgb, and a > 0 where p is already known
//                            (a multiplies the texel's weight: 1 for a known texel)
//   bool el_valid(ivec2 q)   whether q may be a candidate centre (its whole window in the source)
// d is the sum of squared RGB differences over the known texels of the window, each weighted by
// a Gaussian of its distance to p (sigma = N / 6.4, the paper's choice) and normalised by the
// weights present, so a half-known window compares as well as a full one.
#ifndef PASSLAB_IMAGE_EFROS_LEUNG_GLSL
#define PASSLAB_IMAGE_EFROS_LEUNG_GLSL
#include "common/hash.glsl"

#define EL_MAX_TEXELS 121   // N <= 11 (half width h <= 5)

// The known texels of w(p), compacted: offset, colour, normalised weight.
ivec2 el_off[EL_MAX_TEXELS];
vec3 el_col[EL_MAX_TEXELS];
float el_wt[EL_MAX_TEXELS];
int el_count;

void el_gather(ivec2 p, int h) {
    float sigma = float(2 * h + 1) / 6.4;
    float total = 0.0;
    el_count = 0;
    for (int dy = -h; dy <= h; ++dy) {
        for (int dx = -h; dx <= h; ++dx) {
            vec4 c = el_canvas(p + ivec2(dx, dy));
            if (c.a <= 0.0) continue;
            float w = c.a * exp(-float(dx * dx + dy * dy) / (2.0 * sigma * sigma));
            el_off[el_count] = ivec2(dx, dy);
            el_col[el_count] = c.rgb;
            el_wt[el_count] = w;
            total += w;
            ++el_count;
        }
    }
    for (int k = 0; k < el_count; ++k) el_wt[k] /= total;
}

// d(w(p), w(q)) over the gathered texels; stops once the sum passes `limit` (the result is then
// some value > limit).
float el_distance(sampler2D src, ivec2 q, float limit) {
    float sum = 0.0;
    for (int k = 0; k < el_count; ++k) {
        vec3 e = el_col[k] - texelFetch(src, q + el_off[k], 0).rgb;
        sum += el_wt[k] * dot(e, e);
        if (sum > limit) return sum;
    }
    return sum;
}

// Steps 1-3: a first sweep over every valid centre finds d_min; the candidates are the centres
// with d <= d_min (1 + eps) (the paper's threshold, eps = 0.1); a second sweep picks one of them
// with probability proportional to its weight (threshold - d) (closer patches more likely;
// weighted reservoir sampling, one hash per candidate from `seed`, so the choice is repeatable).
// Returns the chosen centre; the caller copies src at it (a value of the source, never a blend).
ivec2 el_choose(sampler2D src, float eps, uvec3 seed) {
    ivec2 size = textureSize(src, 0);
    float d_min = 1e30;
    ivec2 best = ivec2(-1);
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) {
            ivec2 q = ivec2(x, y);
            if (!el_valid(q)) continue;
            float d = el_distance(src, q, d_min);
            if (d < d_min) { d_min = d; best = q; }
        }
    // TODO 2 (003_cfc3b5b225ddab3d.txt L43-45, "centre pixels of the similar patches are the
    // candidates"): sweep every valid centre q again (el_valid) and keep only the candidates,
    // d(q) <= threshold with threshold = d_min (1 + eps); el_distance(src, q, threshold)
    // stops early for the others.
    // TODO 3 (L47, "randomly sample from the candidates weighted by distance d"): choose ONE
    // candidate with probability proportional to w = threshold - d + 1e-12 (the floor makes exact
    // ties, d = threshold = 0, count equally). In one sweep: keep a running sum w_sum of the
    // weights and replace best by q when u * w_sum < w, with u uniform in [0, 1):
    //     float u = float(pcg3d(seed + uvec3(q, 0)).x) * (1.0 / 4294967296.0);
    // (best is the argmin of the first sweep until then.)
    return best;
}
#endif
