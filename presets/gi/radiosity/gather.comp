#version 450
// Pass 1b: solve the radiosity system (000_c9f7e5de708ecbb3.txt L5068-5072: "light transport ->
// linear equation system; solve equation system") by Jacobi iteration, one step per repeat:
//
//     L_i^(n+1) = L0_i + rho_i * sum_j F_ij L_j^(n)
//               = L0_i + rho_i * (1 / N_i) * sum_{k counted} L^(n)_{hit(i, k)}      (formfactors.comp)
//
// with L radiance (radiosity B = pi L), a ray leaving the scene contributing 0. Row n of the
// buffer `radiance` is iterate n (row 0 = L0 from direct.comp), so every iterate stays readable
// and residual.comp can measure how the iteration converges. rho_i * (row sum of F) <= rho_i < 1,
// so the iteration contracts and converges to L = (I - rho F)^-1 L0 (the Neumann series
// L0 + rho F L0 + (rho F)^2 L0 + ..., one more bounce per iteration).
layout(local_size_x = 64) in;

#include "gi/radiosity_albedo.glsl"

layout(std430) readonly buffer Hits { int hit[]; } hits;
layout(std430) buffer Radiance { vec4 value[]; } radiance;

void main() {
    int p = int(gl_GlobalInvocationID.x);
    if (p >= RAD_PATCHES) return;
    int row = pl_iteration;  // reads iterate `row`, writes `row + 1`
    vec3 gathered = vec3(0.0);
    int counted = 0;
    for (int k = 0; k < RAD_RAYS; ++k) {
        int j = hits.hit[p * RAD_RAYS + k];
        if (j == -2) continue;  // sample point inside a block: not part of this patch's surface
        ++counted;
        if (j >= 0) gathered += max(radiance.value[row * RAD_PATCHES + j].rgb, 0.0);  // hidden: -1
    }
    RadSurface s = radiosity_surface(radiosity_surface_of_patch(p));
    // A patch none of whose sample points is visible (floor wholly under a block, the bottoms)
    // has no surface: marked -1 so the tests and the display can tell it from a dark patch.
    vec3 l = counted > 0 ? radiance.value[p].rgb + radiosity_albedo(s) * gathered / float(counted) : vec3(-1.0);
    radiance.value[(row + 1) * RAD_PATCHES + p] = vec4(l, 1.0);
}
