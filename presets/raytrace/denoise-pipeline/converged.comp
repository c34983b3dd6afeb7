#version 450
// Test-only: the converged image the stages approach (000 L5851-5852: "path tracing, ~15 s
// accumulation"): converged_spp samples per pixel per frame of the same scene_sample at this
// frame's G-buffer, averaged over all frames in place (the jittered positions included).
layout(local_size_x = 8, local_size_y = 8) in;
#include "scene.glsl"
uniform sampler2D g_position;
uniform sampler2D g_normal;
layout(rgba32f) uniform image2D converged;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(converged)))) return;
    vec4 pos = texelFetch(g_position, p, 0);
    vec4 gn = texelFetch(g_normal, p, 0);
    vec3 c = kSky;
    if (pos.w > 0.0) {
        c = vec3(0.0);
        for (int k = 0; k < params.converged_spp; ++k)
            c += scene_sample(pos.xyz, gn.xyz, albedo_of(gn.w), scene_random(p, frame.index, uint(k) + 1u));
        c /= float(params.converged_spp);
    }
    if (params.signal == SIGNAL_CONSTANT) c = vec3(0.5);
    uint f = frame.accum_frame;
    imageStore(converged, p, f == 0u ? vec4(c, 1.0) : mix(imageLoad(converged, p), vec4(c, 1.0), 1.0 / float(f + 1u)));
}
