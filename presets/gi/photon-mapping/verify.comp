#version 450
// Test-only (params.verify): the grid gather of gather.comp against brute force. At 64 texels
// spread over every surface, sum the photons within r by visiting all 262144 records instead of
// the grid's cells, and store the relative difference to the light map the frame draws (the two
// sums add the same photons in another order: float rounding only). One work group per texel, its
// 64 threads summing every 64th record (one thread looping over all 262144 stopped early on
// lavapipe, as the first voxelisation loop did), then a shared-memory sum.
layout(local_size_x = 64) in;

shared vec3 partial[64];

#include "gi/photon_map.glsl"
#include "gi/photon_texel.glsl"
#include "gi/radiosity_albedo.glsl"

layout(std430) readonly buffer Photons { vec4 rec[]; } photons;
layout(std430) readonly buffer Radiance { vec4 value[]; } radiance;
layout(std430) writeonly buffer GatherError { float e[]; } gather_error;

void main() {
    int i = int(gl_WorkGroupID.x), lane = int(gl_LocalInvocationID.x);
    int p = (i * 432 + 37) % RAD_PATCHES;  // 432 = 27648 / 64: every surface gets some
    RadSurface s;
    vec3 x, n;
    photon_texel(p, s, x, n);
    vec3 flux = vec3(0.0);
    for (int k = lane; k < PM_RECORDS; k += 64)
        flux += photon_contribution(photons.rec[3 * k], photons.rec[3 * k + 1], photons.rec[3 * k + 2], x, n, params.radius);
    partial[lane] = flux;
    barrier();
    if (lane != 0) return;
    flux = vec3(0.0);
    for (int j = 0; j < 64; ++j) flux += partial[j];
    vec3 brute = photon_radiance(radiosity_albedo(s), flux, params.radius), grid = radiance.value[p].rgb;
    vec3 d = abs(grid - brute) / max(brute, vec3(1e-6));
    gather_error.e[i] = max(d.r, max(d.g, d.b));
}
