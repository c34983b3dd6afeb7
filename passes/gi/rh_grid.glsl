// The radiance-hint grid (002_644d46bdce7e5305.txt L2656-2666: "RH points are the nodes of a 3D
// grid; the grid covers any part of the scene"): RH_N^3 cells over the Cornell box [-1, 1]^3,
// one cascade. Each RH holds the incident radiance around it in 2-band SH (4 coefficients per
// colour channel, gi/sh.glsl's y_0, y_1^-1, y_1^0, y_1^1). The three colour channels are three
// slabs of one 3D image of RH_N x RH_N x 3 RH_N rgba32f texels: channel c of cell (i, j, k) is
// texel (i, j, c RH_N + k), its xyzw the 4 coefficients. A second image holds each RH's minimum
// and maximum distance to the RSM samples it saw (L2692).
#ifndef PASSLAB_GI_RH_GRID_GLSL
#define PASSLAB_GI_RH_GRID_GLSL
#include "gi/sh.glsl"

const int RH_N = 16;
const vec3 RH_LO = vec3(-1.0), RH_HI = vec3(1.0);
const float RH_CELL = 2.0 / float(RH_N);

vec3 rh_cell_center(ivec3 c) { return RH_LO + (vec3(c) + 0.5) * RH_CELL; }

// The 4 basis values y_0, y_1^-1, y_1^0, y_1^1 at w.
vec4 rh_basis(vec3 w) {
    float y[16];
    sh_eval(w, 2, y);
    return vec4(y[0], y[1], y[2], y[3]);
}

// Trilinear SH at world point p from a grid sampled with a linear sampler (clamped to the
// outermost RH centres, so no slab bleeds into the next).
void rh_sample(sampler3D grid, vec3 p, out vec4 r, out vec4 g, out vec4 b) {
    vec3 t = clamp((p - RH_LO) / RH_CELL, vec3(0.5), vec3(float(RH_N) - 0.5));
    vec3 uvw = vec3(t.xy / float(RH_N), t.z / float(3 * RH_N));
    float slab = 1.0 / 3.0;
    r = textureLod(grid, uvw, 0.0);
    g = textureLod(grid, uvw + vec3(0.0, 0.0, slab), 0.0);
    b = textureLod(grid, uvw + vec3(0.0, 0.0, 2.0 * slab), 0.0);
}

// Irradiance over pi from 2-band SH radiance on the hemisphere around n (the integration "over
// the surface-aligned hemisphere", L2747): the clamped cosine's zonal factors are
// A_0 = pi, A_1 = 2 pi / 3, so E(n) / pi = c_0 y_0 + (2/3) sum_m c_1m y_1m(n).
float rh_irradiance_over_pi(vec4 c, vec3 n) {
    vec4 y = rh_basis(n);
    return c.x * y.x + (2.0 / 3.0) * dot(c.yzw, y.yzw);
}

#endif
