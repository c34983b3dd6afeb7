#version 450
// EXERCISE — the TAA resolve. Fill in the three TODO blocks; as shipped it shows this frame's
// own sample and keeps no history (no anti-aliasing at all).
//     passlab run   aa/taa --exercise presets/aa/taa/exercise
//     passlab grade aa/taa --exercise presets/aa/taa/exercise
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
    // TODO 2: reprojection (000 L3488-3505): where was the surface now under this pixel one
    // frame ago? The motion texture holds, per pixel, the uv it moved by since last frame.
    vec2 prev_uv = uv;
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
            // TODO 1: reconstruction weight (000 L3475-3486). aa/shapes.vert moves the geometry by
            // the jitter j (in pixels, the same for every pixel): which scene point does the
            // neighbour (x, y)'s sample show, relative to OUR centre? With d that offset, the
            // Gaussian fit to Blackman-Harris is
            //     W(d) = exp(-2.29 |d|^2)          (kBlackmanHarris = 2.29)
            // With params.reconstruct == RECONSTRUCT_BOX only the pixel's own sample counts
            // (weight 1 for x = y = 0, else 0).
            float w = float(x == 0 && y == 0);
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
    // TODO 3: with params.rectify, clip the history to this frame's 3x3 neighbourhood [lo, hi]
    // (000 L3528-3532), then blend by the exponential moving average of 000 L3471:
    //     s_t = alpha x_t + (1 - alpha) s_(t-1),   x_t = current, s_(t-1) = history,
    //     alpha = params.alpha (the NEW frame's weight: 0.1 by default)
    taa = vec4(current, 1.0);
}
