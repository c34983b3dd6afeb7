#version 450
// Test-only probes. The clamp (gi/vpl_gather.glsl): for every live VPL slot s (texel (s % 32, s / 32)),
// a receiver 2.8 cm in front of it, off its normal by 45 degrees and facing it, where the point
// light's 1/d^2 is close to its singularity. The clamp bounds one VPL's irradiance by
// Phi/pi * 1/c^2 (both cosines <= 1), so r = E_s(x) * pi * c^2 / lum(Phi_s) (luminance-free: the
// green channel) must be <= 1; without the clamp it is cos cos * c^2 / d^2 = 0.5 * 0.01 / 0.0008 = 6.25.
layout(local_size_x = 8, local_size_y = 8) in;
#include "gi/vpl_gather.glsl"
layout(rgba32f) uniform writeonly image2D clamp_probe, map_means;

// The mean depth of VPL slot s's shadow map (map_means: the incremental test compares the maps
// themselves, not only the picture, to which one stale map of 64 adds < 1/255).
float map_mean(uint s) {
    ivec2 size = textureSize(vpl_maps, 0).xy;
    float sum = 0.0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) sum += texelFetch(vpl_maps, ivec3(x, y, int(s)), 0).r;
    return sum / float(size.x * size.y);
}
void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(q, imageSize(clamp_probe)))) return;
    uint s = uint(q.y * 32 + q.x);
    float r = 0.0;
    if (s < vpl_args.slots && vpls.vpl[s].position.w > 0.0) {
        Vpl v = vpls.vpl[s];
        mat3 f = vpl_frame(normalize(v.normal.xyz));
        vec3 off = 0.02 * (f[2] + f[0]);
        vec3 x = v.position.xyz + off;
        vec3 e = ir_vpl_irradiance(v, s, x, -normalize(off));
        r = v.flux.g > 0.0 ? e.g * 3.14159265 * params.clamp * params.clamp / v.flux.g : 0.0;
    }
    imageStore(clamp_probe, q, vec4(r, r, r, 1.0));
    float m = s < vpl_args.slots ? map_mean(s) : 0.0;
    imageStore(map_means, q, vec4(m, m, m, 1.0));
}
