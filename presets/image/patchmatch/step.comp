#version 450
// One sub-step of a PatchMatch iteration (003_cfc3b5b225ddab3d.txt L93-184; Barnes et al. 2009).
// An iteration is 8 sub-steps: 0..6 propagate, 7 is the random search. The pass runs
// `substeps` times a frame (nnf_in/nnf_out ping-pong), so sub-step g = accum_frame * substeps +
// pl_iteration of the run is sub-step g % 8 of iteration g / 8: with substeps = 8 (the tests)
// a frame is an iteration, with 2 (the live view) an iteration takes 4 frames.
//
// Propagation (L148-158): with a = (x, y), the candidates are f(x-1, y) + (1, 0) and
// f(x, y-1) + (0, 1); "next iteration, use bottom and right neighbours": f(x+1, y) - (1, 0),
// f(x, y+1) - (0, 1). A candidate replaces f(a) only if d(a, candidate) < d(a, f(a)).
// The paper scans the image in order, so f(x-1, y) is already this iteration's; here every
// pixel runs in parallel and reads the previous sub-step's field (Jacobi). A good match then
// travels one pixel per sub-step, so with `jump` the sub-steps use the neighbour at distance
// s = 64, 32, ..., 1 instead (jump flooding, the GPU variant of the paper's section 3.2):
// candidate f(x - s, y) + (s, 0). Over 7 sub-steps a match reaches any pixel of a 128-texel
// image; the fields converge differently from the sequential scan (README).
//
// Random search (L175-183): candidates v0 + w alpha^i R_i, v0 = the best match so far,
// R_i uniform in [-1, 1]^2, w = the image width, alpha = 1/2, for every i with w alpha^i >= 1.
#include "common/hash.glsl"
#include "image/patch.glsl"
#include "image/nnf.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D A;
uniform sampler2D B;
uniform sampler2D nnf_in;
layout(rgba32f) uniform writeonly image2D nnf_out;

ivec2 g_a;        // the patch of A this thread improves
ivec2 g_best;     // f(a) so far
float g_best_d;   // d(a, f(a))

// Replace f(a) by candidate b (clamped to a valid centre of B) if it is strictly closer.
void try_candidate(ivec2 b) {
    b = patch_clamp_centre(b, textureSize(B, 0), params.patch_radius);
    float d = patch_ssd(A, g_a, B, b, params.patch_radius, g_best_d);
    if (d < g_best_d) { g_best = b; g_best_d = d; }
}

ivec2 f_at(ivec2 q) { return nnf_target(texelFetch(nnf_in, q, 0)); }
bool in_a(ivec2 q) { return all(greaterThanEqual(q, ivec2(0))) && all(lessThan(q, textureSize(A, 0))); }

// Propagation from the neighbours at distance s: left and top on even iterations, right and
// bottom on odd ones (L156-158).
void propagate(int s, int iteration) {
    int sgn = (iteration % 2 == 0) ? 1 : -1;
    ivec2 ex = ivec2(s * sgn, 0), ey = ivec2(0, s * sgn);
    // f(x - s, y) + (s, 0): the neighbour's match moved by the same step, so that a shifted
    // copy keeps its offset f(a) - a.
    if (in_a(g_a - ex)) try_candidate(f_at(g_a - ex) + ex);
    if (in_a(g_a - ey)) try_candidate(f_at(g_a - ey) + ey);
}

// Random search around the best match so far, radius halving from the image width down to 1.
void random_search(int iteration) {
    float w = float(textureSize(B, 0).x);
    const float alpha = 0.5;
    uint seed = uint(params.seed) * 7919u + uint(iteration) * 104729u;
    for (int i = 0; w * pow(alpha, float(i)) >= 1.0; ++i) {
        float radius = w * pow(alpha, float(i));
        vec2 R = vec2(pcg3d(uvec3(g_a, seed + uint(i))).xy) * (2.0 / 4294967296.0) - 1.0;
        try_candidate(g_best + ivec2(round(radius * R)));
    }
}

void main() {
    g_a = ivec2(gl_GlobalInvocationID.xy);
    if (!in_a(g_a)) return;
    vec4 cur = texelFetch(nnf_in, g_a, 0);
    g_best = nnf_target(cur);
    g_best_d = nnf_distance(cur);
    int g = frame.accum_frame * pl_iteration_count + pl_iteration;
    int iteration = g / 8, sub = g % 8;
    if (sub < 7)
        propagate(params.jump ? 1 << (6 - sub) : 1, iteration);
    else
        random_search(iteration);
    imageStore(nnf_out, g_a, nnf_encode(g_best, g_best_d));
}
