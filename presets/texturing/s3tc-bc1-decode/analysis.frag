#version 450
// Per-texel measurements for the tests (float targets, one fragment per texel):
//   err   rgb: |hardware - source| per channel on opaque source texels (0 on transparent ones)
//         a:   alpha error |hardware alpha - (source alpha >= 0.5)| (punch-through alpha)
//   dist  r:   Euclidean RGB error |hardware - source| of opaque texels, in 8-bit steps
//         g, b, a: 1 where the index picks a third, the half, an endpoint or transparent black
//             (their means say how much of the texture each check below covers)
//   check x:   |shader - hardware| (largest of RGBA) where the index picks an endpoint (0, 1)
//             or, in three-colour mode, the transparent black (3); 0 elsewhere
//         y:   the same where the index picks a third, (2 c0 + c1)/3 or (c0 + 2 c1)/3
//         z:   the same where the index picks the half (c0 + c1)/2 of three-colour mode
//         w:   one-colour round trip, in 8-bit steps: |hardware - source| minus the distance
//             from the source to the nearest colour RGB565 can represent, largest channel; the
//             nearest is found by searching all 32 / 64 codes (not by the encoder's formula)
#include "texturing/bc1.glsl"
layout(location = 0) out vec4 err;
layout(location = 1) out vec4 dist;
layout(location = 2) out vec4 check;
uniform sampler2D src;
uniform sampler2D hw;
uniform sampler2D sw;
layout(std430) readonly buffer Blocks { uvec2 words[]; } blocks;

// Distance (8-bit steps) from v (0..255) to the nearest n-bit code expanded by replication.
float nearest_code_distance(float v, int bits) {
    float best = 255.0;
    for (int q = 0; q < (1 << bits); ++q) {
        int e = (q << (8 - bits)) | (q >> (2 * bits - 8));
        best = min(best, abs(float(e) - v));
    }
    return best;
}

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    vec4 s = texelFetch(src, t, 0);
    vec4 h = texelFetch(hw, t, 0);
    vec4 d = texelFetch(sw, t, 0);
    bool opaque = s.a >= 0.5;
    vec3 e = opaque ? abs(h.rgb - s.rgb) : vec3(0.0);
    err = vec4(e, abs(h.a - (opaque ? 1.0 : 0.0)));

    uvec2 block = blocks.words[bc1_block_of(t, textureSize(hw, 0).x)];
    uint index = bc1_index(block, bc1_in_block(t));
    bool three = bc1_three_colour(block);
    bool third = !three && index >= 2u;
    bool half_ = three && index == 2u;
    vec4 diff = abs(d - h);
    float m = max(max(diff.r, diff.g), max(diff.b, diff.a));

    dist = vec4(length(e) * 255.0, third ? 1.0 : 0.0, half_ ? 1.0 : 0.0, third || half_ ? 0.0 : 1.0);

    vec3 s8 = floor(s.rgb * 255.0 + 0.5);
    vec3 nearest = vec3(nearest_code_distance(s8.r, 5), nearest_code_distance(s8.g, 6), nearest_code_distance(s8.b, 5));
    vec3 excess = opaque ? abs(h.rgb * 255.0 - s8) - nearest : vec3(0.0);
    check = vec4(third || half_ ? 0.0 : m, third ? m : 0.0, half_ ? m : 0.0, max(max(excess.r, excess.g), excess.b));
}
