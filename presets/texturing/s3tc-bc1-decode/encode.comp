#version 450
// BC1 encoder, one invocation per 4x4 block (000_c9f7e5de708ecbb3.txt L1629-1641 describes the
// format and its decoding; how to choose the two colours is left to the encoder, so this part
// is ours, stated here):
//  1. endpoints, in 8-bit RGB over the block's opaque texels:
//       bbox: the bounding box's corners lo = min, hi = max per channel, with the diagonal fix:
//             a channel whose covariance with the widest channel is negative swaps lo and hi
//             (without it a block where R rises while B falls gets the wrong diagonal of the
//             box, and every colour between is missed; break it with params.diagonal_fix)
//       pca:  the principal axis of the colours (power iteration on their 3x3 covariance,
//             kPowerSteps steps from the fixed box diagonal), endpoints = the mean + the
//             extreme projections of the texels onto it
//  2. quantise both to the nearest RGB565 (bc1_quantize565)
//  3. mode: a block with a transparent texel (alpha < 0.5) uses three colours + transparent
//     (color0 <= color1, index 3 for those texels); an opaque one four colours (color0 > color1;
//     equal endpoints - a one-colour block - leave three equal colours, index 0 exact)
//  4. each opaque texel takes the index of the palette colour nearest to it (squared RGB
//     distance, the palette decoded exactly as bc1_palette does; no refinement iterations)
#include "texturing/bc1.glsl"
layout(local_size_x = 64) in;
uniform sampler2D src;
layout(std430) writeonly buffer Blocks { uvec2 words[]; } blocks;

const int kTexels = kBc1BlockSide * kBc1BlockSide;   // 16
const int kPowerSteps = 8;                           // power iterations for the principal axis
const float kOpaque = 0.5;                           // punch-through alpha threshold

void main() {
    ivec2 size = textureSize(src, 0) / kBc1BlockSide;   // blocks per row and column
    uint id = gl_GlobalInvocationID.x;
    if (id >= uint(size.x * size.y)) return;
    ivec2 origin = ivec2(int(id) % size.x, int(id) / size.x) * kBc1BlockSide;

    vec3 c[kTexels];
    bool opaque[kTexels];
    bool any_transparent = false;
    int n = 0;
    vec3 lo = vec3(255.0), hi = vec3(0.0), mean = vec3(0.0);
    for (int i = 0; i < kTexels; ++i) {
        vec4 t = texelFetch(src, origin + ivec2(i % kBc1BlockSide, i / kBc1BlockSide), 0);
        c[i] = floor(t.rgb * 255.0 + 0.5);   // the rgba8 source's integers
        opaque[i] = t.a >= kOpaque;
        if (!opaque[i]) { any_transparent = true; continue; }
        lo = min(lo, c[i]);
        hi = max(hi, c[i]);
        mean += c[i];
        ++n;
    }

    vec3 e0 = vec3(0.0), e1 = vec3(0.0);
    if (n > 0) {
        mean /= float(n);
        mat3 cov = mat3(0.0);
        for (int i = 0; i < kTexels; ++i) {
            if (!opaque[i]) continue;
            vec3 d = c[i] - mean;
            cov += outerProduct(d, d);
        }
        // Bounding box with the diagonal fix.
        vec3 range = hi - lo;
        int widest = range.x >= range.y && range.x >= range.z ? 0 : (range.y >= range.z ? 1 : 2);
        e0 = hi;
        e1 = lo;
        if (params.diagonal_fix) {
            for (int k = 0; k < 3; ++k) {
                if (cov[widest][k] < 0.0) { e0[k] = lo[k]; e1[k] = hi[k]; }
            }
        }
        if (params.endpoints == ENDPOINTS_PCA) {
            vec3 axis = e0 - e1;
            for (int s = 0; s < kPowerSteps; ++s) {
                vec3 next = cov * axis;
                float len = length(next);
                axis = len > 1e-6 ? next / len : vec3(0.0);
            }
            float tmin = 0.0, tmax = 0.0;
            for (int i = 0; i < kTexels; ++i) {
                if (!opaque[i]) continue;
                float t = dot(c[i] - mean, axis);
                tmin = min(tmin, t);
                tmax = max(tmax, t);
            }
            e0 = clamp(mean + axis * tmax, 0.0, 255.0);
            e1 = clamp(mean + axis * tmin, 0.0, 255.0);
        }
    }

    uint q0 = bc1_quantize565(e0), q1 = bc1_quantize565(e1);
    // Mode by the order of the two 16-bit words (swapping them swaps which colour is c0).
    bool want_three = any_transparent;
    if (want_three ? q0 > q1 : q0 < q1) { uint s = q0; q0 = q1; q1 = s; }
    vec4 pal[4];
    bc1_palette(q0, q1, pal);
    int usable = q0 > q1 ? 4 : 3;   // index 3 is transparent black in three-colour mode

    uint bits = 0u;
    for (int i = 0; i < kTexels; ++i) {
        uint best = 3u;
        if (opaque[i]) {
            float best_d = 1e30;
            for (int k = 0; k < usable; ++k) {
                vec3 d = pal[k].rgb - c[i];
                float dd = dot(d, d);
                if (dd < best_d) { best_d = dd; best = uint(k); }
            }
        }
        bits |= best << (2u * uint(i));
    }
    blocks.words[id] = uvec2(q0 | (q1 << 16), bits);
}
