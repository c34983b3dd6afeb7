#version 450
// Pass 2 of photon mapping (000_c9f7e5de708ecbb3.txt L5091-5109): at a surface point x, collect
// the photons inside the sphere of radius r; their flux per area is the irradiance ("number of
// photons = intensity at point x"), and a diffuse surface reflects
//
//     L(x) = (rho / pi) * sum_{|x_p - x| < r, n_p . n > 0.5} Phi_p / (pi r^2)
//
// A small radius gathers few photons: noise; a large one averages over detail: blur (L5101-5107).
// The photons of every bounce are gathered, so this is the whole image, direct light included,
// read from the map alone (no shadow rays: the shadows are where no photons landed).
//
// The scene is static, so the estimate is baked at the centre of every texel of a light map
// (the patches of gi/radiosity_patches.glsl at 64 x 64 per wall, 16 x 16 per block face): the
// course's "render cache" of outgoing radiance on surface points (L5111-5120). Per fragment it
// cost 2.3 s a frame on lavapipe; baked it is ~0.3 s once, and the frame draws the light map.
layout(local_size_x = 64) in;

#include "gi/photon_map.glsl"
#include "gi/photon_texel.glsl"
#include "gi/radiosity_albedo.glsl"

layout(std430) readonly buffer Photons { vec4 rec[]; } photons;
layout(std430) readonly buffer Start { uint start[]; } starts;
layout(std430) readonly buffer Sorted { uint record[]; } sorted;
layout(std430) writeonly buffer Radiance { vec4 value[]; } radiance;

void main() {
    int p = int(gl_GlobalInvocationID.x);
    if (p >= RAD_PATCHES) return;
    RadSurface s;
    vec3 x, n;
    photon_texel(p, s, x, n);
    float r = params.radius;
    ivec3 lo = photon_cell_coords(x - r), hi = photon_cell_coords(x + r);
    vec3 flux = vec3(0.0);
    for (int cz = lo.z; cz <= hi.z; ++cz)
        for (int cy = lo.y; cy <= hi.y; ++cy)
            for (int cx = lo.x; cx <= hi.x; ++cx) {
                int c = photon_cell_index(ivec3(cx, cy, cz));
                for (uint i = starts.start[c]; i < starts.start[c + 1]; ++i) {
                    uint k = 3u * sorted.record[i];
                    flux += photon_contribution(photons.rec[k], photons.rec[k + 1u], photons.rec[k + 2u], x, n, r);
                }
            }
    radiance.value[p] = vec4(photon_radiance(radiosity_albedo(s), flux, r), 1.0);
}
