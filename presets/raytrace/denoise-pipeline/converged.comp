#version 450
// Test-only: the converged image the stages approach (000 L5851-5852: "path tracing, ~15 s
// accumulation"): converged_spp samples per pixel per frame of the same scene_sample at this
// frame's G-buffer, averaged over all frames in place (the jittered positions included).
layout(local_size_x = 8, local_size_y = 8) in;
#include "scene.glsl"
uniform sampler2D g_position;
uniform sampler2D g_normal;
layout(rgba32f) uniform image2D converged;
layout(r8) writeonly uniform image2D edges;  // 1: another surface (mesh or sky) within 2 pixels

// Pixels near a silhouette, where a filter that ignores the geometry mixes surfaces: the 5x5
// window (spatial_radius 2) holds another mesh or the sky.
bool near_edge(ivec2 p, float mesh) {
    ivec2 top = imageSize(edges) - 1;
    for (int k = 0; k < 25; ++k) {
        ivec2 q = clamp(p + ivec2(k % 5 - 2, k / 5 - 2), ivec2(0), top);
        if (texelFetch(g_position, q, 0).w == 0.0 || texelFetch(g_normal, q, 0).w != mesh) return true;
    }
    return false;
}

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(converged)))) return;
    vec4 pos = texelFetch(g_position, p, 0);
    vec4 gn = texelFetch(g_normal, p, 0);
    vec3 c = kSky;
    imageStore(edges, p, vec4(pos.w > 0.0 && near_edge(p, gn.w) ? 1.0 : 0.0));
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
