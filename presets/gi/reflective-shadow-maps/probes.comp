#version 450
// Test-only probes of the gather in world space (not through the view), 32x32 points over the
// floor (y = -0.999): `floor_probe` = E(x) / flux_scale with the floor's normal +Y, `away_probe`
// = E at the same points just under the floor with the normal turned down, -Y, away from every RSM texel (each lies on or above the
// floor: n . (x_p - x) <= 0 for all of them, so the receiver's cosine must zero every term).
// The view camera cannot change either: the RSM and the gather read only the light's camera.
layout(local_size_x = 8, local_size_y = 8) in;
#include "gather.glsl"
layout(rgba32f) uniform writeonly image2D floor_probe, away_probe;
void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(q, imageSize(floor_probe)))) return;
    vec2 xz = (vec2(q) + 0.5) / vec2(imageSize(floor_probe)) * 1.9 - 0.95;
    vec3 x = vec3(xz.x, -0.999, xz.y);
    imageStore(floor_probe, q, vec4(rsm_irradiance(x, vec3(0, 1, 0)) / params.flux_scale, 1.0));
    // just under the floor (y = -1.01), so that even the floor's own texels lie above it
    imageStore(away_probe, q, vec4(rsm_irradiance(vec3(x.x, -1.01, x.z), vec3(0, -1, 0)), 1.0));
}
