// The radiance-hint grid (002_644d46bdce7e5305.txt L2656-2666: "RH points are the nodes of a 3D
// grid; the grid covers any part of the scene") in params.cascades nested cascades (L2589: the
// engine's "four nested world-snapped 32^3 cascades"; here 1..3 of RH_N^3 over the Cornell box).
// Cascade K - 1 (K = params.cascades) covers the box [-1, 1]^3; each finer one has half its
// parent's cell and extent, centred on params.cascade_center, snapped to its own cell in world
// space (so it does not swim when the centre moves) and kept inside the box.
// Each RH holds the incident radiance around it in 2-band SH (4 coefficients per colour
// channel, gi/sh.glsl's y_0, y_1^-1, y_1^0, y_1^1). One 3D image of RH_N x RH_N x RH_DEPTH
// rgba32f texels holds them all: channel ch of cascade k's cell (i, j, l) is texel
// (i, j, (3 k + ch) RH_N + l), its xyzw the 4 coefficients (with one cascade: three slabs of
// RH_N). A second image holds each RH's minimum and maximum distance to the RSM samples it saw
// (L2692), cascade k's cell (i, j, l) at texel (i, j, k RH_N + l).
#ifndef PASSLAB_GI_RH_GRID_GLSL
#define PASSLAB_GI_RH_GRID_GLSL
#include "gi/sh.glsl"

const int RH_N = 16;
const int RH_CASCADES_MAX = 3;
const int RH_DEPTH = 3 * RH_N * RH_CASCADES_MAX;
const vec3 RH_LO = vec3(-1.0), RH_HI = vec3(1.0);
const float RH_CELL = 2.0 / float(RH_N);  // the outermost cascade's cell
// A fragment reads the grid this far above its surface (L2742: "half a cell"), the outermost
// cell's half in every cascade: the tap point is the same world point whichever cascade answers.
const float RH_TAP_OFFSET = 0.5 * RH_CELL;
// Cascade k fades into its parent over this many of its own cells inside its border (the
// "cascade blending" of L2589's Blended Cascaded RH).
const float RH_BLEND_CELLS = 2.0;

int rh_cascades() { return clamp(int(params.cascades), 1, RH_CASCADES_MAX); }
float rh_cell(int k) { return RH_CELL * exp2(float(k - (rh_cascades() - 1))); }
vec3 rh_lo(int k) {
    if (k >= rh_cascades() - 1) return RH_LO;
    float cell = rh_cell(k), extent = cell * float(RH_N);
    vec3 lo = floor((params.cascade_center - 0.5 * extent) / cell + 0.5) * cell;  // world-snapped
    return clamp(lo, RH_LO, RH_HI - extent);
}
vec3 rh_cell_center(int k, ivec3 c) { return rh_lo(k) + (vec3(c) + 0.5) * rh_cell(k); }
ivec3 rh_texel(int k, int ch, ivec3 c) { return ivec3(c.xy, (3 * k + ch) * RH_N + c.z); }
ivec3 rh_dist_texel(int k, ivec3 c) { return ivec3(c.xy, k * RH_N + c.z); }

// How much cascade k answers at p: 1 inside, falling linearly to 0 over RH_BLEND_CELLS of its
// cells towards the outermost hint centres (beyond them its lookup would only clamp). A side that
// lies on the box's wall does not fade: its parent clamps there too and is only coarser.
float rh_cascade_weight(int k, vec3 p) {
    if (k >= rh_cascades() - 1) return 1.0;
    float cell = rh_cell(k);
    vec3 lo = rh_lo(k), hi = lo + float(RH_N) * cell;
    vec3 below = mix(p - (lo + 0.5 * cell), vec3(1e9), lessThanEqual(lo, RH_LO + 1e-6));
    vec3 above = mix(hi - 0.5 * cell - p, vec3(1e9), greaterThanEqual(hi, RH_HI - 1e-6));
    vec3 inside = min(below, above);
    return clamp(min(inside.x, min(inside.y, inside.z)) / (RH_BLEND_CELLS * cell), 0.0, 1.0);
}

// Whether this frame recomputes the grid the fragments read (seed, bounces, commit): not once it
// is cached (params.rh_frames frames after a change), and while it converges only on every
// params.rh_update-th frame, always including the last before the cache, so the cached grid is
// the exchange of the final mean. Between updates the fragments read the last exchanged grid,
// at most rh_update - 1 frames of injection behind.
// Cached: params.rh_frames frames since the last change have taken their RSM samples.
bool rh_cached() { return frame.accum_frame >= uint(max(params.rh_frames, 1)); }
bool rh_exchange_runs() {
    if (rh_cached()) return false;
    uint k = frame.accum_frame;
    return k + 1u == uint(max(params.rh_frames, 1)) || k % uint(max(params.rh_update, 1)) == 0u;
}

// The 4 basis values y_0, y_1^-1, y_1^0, y_1^1 at w.
vec4 rh_basis(vec3 w) {
    float y[16];
    sh_eval(w, 2, y);
    return vec4(y[0], y[1], y[2], y[3]);
}

// Trilinear SH of cascade k at world point p from a grid sampled with a linear sampler
// (clamped to the cascade's outermost RH centres, so no slab bleeds into the next).
void rh_sample_cascade(sampler3D grid, int k, vec3 p, out vec4 r, out vec4 g, out vec4 b) {
    vec3 t = clamp((p - rh_lo(k)) / rh_cell(k), vec3(0.5), vec3(float(RH_N) - 0.5));
    vec3 uvw = vec3(t.xy / float(RH_N), (float(3 * k * RH_N) + t.z) / float(RH_DEPTH));
    float slab = float(RH_N) / float(RH_DEPTH);
    r = textureLod(grid, uvw, 0.0);
    g = textureLod(grid, uvw + vec3(0.0, 0.0, slab), 0.0);
    b = textureLod(grid, uvw + vec3(0.0, 0.0, 2.0 * slab), 0.0);
}

// The SH at p from the finest cascade that answers there, blended with its parent in the fade
// band: w fine + (1 - w) parent, so a field both represent exactly is read exactly across the
// border.
void rh_sample(sampler3D grid, vec3 p, out vec4 r, out vec4 g, out vec4 b) {
    r = g = b = vec4(0.0);
    for (int k = 0; k < rh_cascades(); ++k) {
        float w = rh_cascade_weight(k, p);
        if (w <= 0.0) continue;
        rh_sample_cascade(grid, k, p, r, g, b);
        if (w < 1.0) {
            vec4 pr, pg, pb;
            rh_sample_cascade(grid, k + 1, p, pr, pg, pb);
            r = mix(pr, r, w);
            g = mix(pg, g, w);
            b = mix(pb, b, w);
        }
        return;
    }
}

// r_min, r_max of cascade k's hint whose cell holds q (the nearest one for q outside it).
vec2 rh_distances(sampler3D dist, int k, vec3 q) {
    ivec3 qc = clamp(ivec3(floor((q - rh_lo(k)) / rh_cell(k))), ivec3(0), ivec3(RH_N - 1));
    return texelFetch(dist, rh_dist_texel(k, qc), 0).xy;
}

// Irradiance over pi from 2-band SH radiance on the hemisphere around n (the integration "over
// the surface-aligned hemisphere", L2747): the clamped cosine's zonal factors are
// A_0 = pi, A_1 = 2 pi / 3, so E(n) / pi = c_0 y_0 + (2/3) sum_m c_1m y_1m(n).
float rh_irradiance_over_pi(vec4 c, vec3 n) {
    vec4 y = rh_basis(n);
    return c.x * y.x + (2.0 / 3.0) * dot(c.yzw, y.yzw);
}

#endif
