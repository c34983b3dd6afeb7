#version 450
// Progressive path tracing (passes/gi/pathtrace.glsl): params.spp new paths per pixel this
// frame, averaged into the running mean of every earlier frame's since the accumulation last
// reset (frame.accum_frame = 0 after any param or camera change, docs/format.md):
//     mean_j = mean_{j-1} + (batch_j - mean_{j-1}) / (j + 1),   j = the pixel's batch index
// Every batch has spp samples, so this is the plain mean of all (j + 1) spp samples.
// Sample s of batch j has index j * spp + s: its random numbers depend only on the pixel, that
// index and the vertex, so a render is reproducible and estimates that keep different terms
// trace the same paths. The eye ray goes through the pixel centre (no jitter), so the reference
// agrees with rasterised methods at edges.
//
// The live view interleaves (interleave.glsl): this pass runs on ceil(view / k) threads, each
// tracing one pixel of its k x k tile, the tile's cell of this frame. The means are updated in
// place (each pixel is read and written by its one invocation); carry.comp (before it) zeroes
// the pixels not yet traced since a reset. Alpha is 1 once a pixel has a sample.
//
// Estimates: `radiance` (the terms params.only_length selects), and with params.split also
// `l0` (only L0) and `l1` (only L1), each from its own pathtrace_radiance call over the same
// samples. One loop over them, not one pass each: the path tracer is inlined once, and
// llvmpipe's compile of it (seconds on a loaded machine, counted by the 20 s frame watchdog)
// happens once.
#include "gi/pathtrace.glsl"
#include "interleave.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f) uniform image2D radiance;
layout(rgba32f) uniform image2D l0;
layout(rgba32f) uniform image2D l1;

void main() {
    uint n = uint(max(frame.accum_frame, 0));
    ivec2 p = pt_traced_pixel(ivec2(gl_GlobalInvocationID.xy), n);
    ivec2 size = imageSize(radiance);
    if (any(greaterThanEqual(p, size))) return;
    uint batch_index = n / uint(pt_interleave() * pt_interleave());
    pathtrace_scene_init(params.scene);
    pathtrace_seed = uint(params.seed);
    vec2 ndc = (vec2(p) + 0.5) / vec2(size) * 2.0 - 1.0;
    vec4 far_point = frame.inv_view_proj * vec4(ndc, 1.0, 1.0);
    vec3 ro = frame.camera_pos.xyz;
    vec3 rd = normalize(far_point.xyz / far_point.w - ro);
    int spp = max(params.spp, 1);
    for (int e = 0; e < (params.split ? 3 : 1); ++e) {
        int keep = e == 0 ? params.only_length : e - 1;
        vec3 batch = vec3(0.0);
        for (int s = 0; s < spp; ++s)
            batch += pathtrace_radiance(ro, rd, uvec2(p), batch_index * uint(spp) + uint(s), params.bounces, keep);
        batch /= float(spp);
        vec3 prev = (e == 0 ? imageLoad(radiance, p) : (e == 1 ? imageLoad(l0, p) : imageLoad(l1, p))).rgb;
        vec4 mean = vec4(batch_index == 0u ? batch : mix(prev, batch, 1.0 / float(batch_index + 1u)), 1.0);
        if (e == 0) imageStore(radiance, p, mean);
        else if (e == 1) imageStore(l0, p, mean);
        else imageStore(l1, p, mean);
    }
}
