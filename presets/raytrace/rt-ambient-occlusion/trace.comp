#version 450
// Ray-traced AO per G-buffer texel (passes/raytrace/rtao.glsl), averaged over frames in place.
// STRIDE: the G-buffer texel of AO texel p is p * STRIDE (2: the view's AO at half resolution,
// 000 L5790 "trace at 50% resolution"; 1: the test's G-buffer of vertices).
layout(local_size_x = 8, local_size_y = 8) in;
#include "raytrace/rtao.glsl"
uniform sampler2D g_position;
uniform sampler2D g_normal;
layout(r32f) uniform image2D ao;  // running mean of V; frame 0 (accum_frame) restarts it

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(ao)))) return;
    // interleave k (issue #21): after the first frame, a texel traces one frame in k, in turn
    // (k = 2: a checkerboard; 3: diagonals; 4: one texel of each 2x2), so a still view sends 1/k of the rays per
    // frame. Frame 0 (accum_frame: any camera or param change) traces every texel, so a moving
    // view is never stale. n counts the texel's own traced frames: its cells and its running mean
    // are the k = 1 ones, only later (after n traced frames, not n frames).
    int k = params.interleave, f = int(frame.accum_frame);
    int turn = k == 4 ? (p.x & 1) + 2 * (p.y & 1) : (p.x + p.y) % k;
    if (f > 0 && (f - 1) % k != turn) return;  // not this texel's frame: its mean stays
    int n = f == 0 ? 0 : 1 + (f - 1) / k;
    ivec2 g = min(p * STRIDE, textureSize(g_position, 0) - 1);
    vec4 pos = texelFetch(g_position, g, 0);
    float v = 1.0;  // sky: nothing to occlude
    if (pos.w > 0.0) {
        int first = n * params.batch;
        v = rtao_visibility(pos.xyz, normalize(texelFetch(g_normal, g, 0).xyz), p, first, params.batch, params.rays, params.max_distance);
    }
    imageStore(ao, p, vec4(rtao_accumulate(imageLoad(ao, p).r, v, uint(n))));
}
