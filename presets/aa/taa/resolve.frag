#version 450
// The TAA resolve (000_c9f7e5de708ecbb3.txt L3385-3554):
//  1. reconstruct this frame at the pixel centre from the 3x3 jittered samples, weighted by
//     exp(-2.29 d^2) (a Gaussian fit to Blackman-Harris of width 3.3, L3475-3486; every pixel
//     shares the jitter, so the weights are the same everywhere) — or the pixel's own sample;
//  2. reproject: last frame's result at uv - motion (L3488-3505);
//  3. reject it (alpha = 1) where the object seen there last frame is nowhere in this pixel's
//     3x3 neighbourhood now (L3516-3522; comparing with the pixel's own ID alone would reject
//     every edge pixel, whose ID flips with the jitter, and undo the anti-aliasing);
//  4. rectify: clip it to the min/max of this frame's 3x3 neighbourhood (L3528-3532);
//  5. s_t = alpha x_t + (1 - alpha) s_(t-1)   (L3461-3471, alpha = 0.1).
#include "aa/taa_jitter.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 taa;
uniform sampler2D cur;
uniform sampler2D motion;
uniform sampler2D id;
uniform sampler2D id_prev;
uniform sampler2D taa_prev;

const float kBlackmanHarris = 2.29;

void main() {
    ivec2 px = ivec2(gl_FragCoord.xy), last = ivec2(frame.resolution.xy) - 1;
    vec2 j = taa_jitter(frame.index, params.jitter);
    vec2 prev_uv = uv - texelFetch(motion, px, 0).xy;
    float prev_id = texture(id_prev, prev_uv).r;
    bool id_nearby = false;
    vec3 sum = vec3(0.0), lo = vec3(1e30), hi = vec3(-1e30);
    float wsum = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) {
            ivec2 q = clamp(px + ivec2(x, y), ivec2(0), last);
            id_nearby = id_nearby || texelFetch(id, q, 0).r == prev_id;
            vec3 c = texelFetch(cur, q, 0).rgb;
            lo = min(lo, c), hi = max(hi, c);
            // Where this neighbour's sample lies, seen from our centre. aa/shapes.vert moves the
            // geometry by +j pixels, so a pixel centre sees the scene point at centre - j
            // (the catalogue's pitfall: the jitter's sign; it used to be + j here, which reconstructs
            // from samples mirrored through the centre: blackman-harris-converges 0.569, not 0.351).
            vec2 d = vec2(x, y) - j;
            float w = params.reconstruct == RECONSTRUCT_BOX ? float(x == 0 && y == 0) : exp(-kBlackmanHarris * dot(d, d));
            sum += w * c, wsum += w;
        }
    vec3 current = sum / wsum;
    bool outside = any(lessThan(prev_uv, vec2(0.0))) || any(greaterThan(prev_uv, vec2(1.0)));
    bool moved_object = params.reject && !id_nearby;
    if (frame.index == 0 || outside || moved_object) {
        taa = vec4(current, 1.0);  // no usable history: this frame only
        return;
    }
    vec3 history = texture(taa_prev, prev_uv).rgb;
    if (params.rectify) history = clamp(history, lo, hi);
    taa = vec4(mix(history, current, params.alpha), 1.0);
}
