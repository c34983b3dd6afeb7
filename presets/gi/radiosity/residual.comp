#version 450
// How the solve converges: residual[n] = max over patches and channels of |L^(n+1) - L^(n)|, the
// residual of iterate n (L0 + rho F L^(n) - L^(n) is exactly the next Jacobi update). The
// iteration matrix rho F has row sums <= max rho < 1, so in the max norm every update is at
// most max rho times the previous one: the residuals never increase (the `sorted` check).
layout(local_size_x = 32) in;

#include "gi/radiosity_patches.glsl"

layout(std430) readonly buffer Radiance { vec4 value[]; } radiance;
layout(std430) writeonly buffer Residual { float r[]; } residual;

void main() {
    int n = int(gl_GlobalInvocationID.x);
    if (n >= RAD_MAX_ITERATIONS) return;
    float r = 0.0;
    if (n < params.iterations) {
        for (int p = 0; p < RAD_LIVE_PATCHES; ++p) {
            vec3 d = abs(radiance.value[(n + 1) * RAD_PATCHES + p].rgb - radiance.value[n * RAD_PATCHES + p].rgb);
            r = max(r, max(d.r, max(d.g, d.b)));
        }
    }
    residual.r[n] = r;
}
