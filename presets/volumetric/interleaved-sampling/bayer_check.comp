#version 450
// Test pass: the histogram of 16 x bayer4 over one 4 x 4 tile (16 threads): a permutation of
// {0..15} has every bin exactly 1. It also bins interleave_offset's value (offset - 1/32) * 16,
// the offset the march uses, into bins 16..31.
#include "volumetric/interleave.glsl"
layout(local_size_x = 4, local_size_y = 4) in;
layout(std430) buffer Hist { uint bin[32]; } hist;
void main() {
    ivec2 p = ivec2(gl_LocalInvocationID.xy) + ivec2(4 * 7, 4 * 3);   // any tile: p & 3 repeats
    uint v = uint(bayer4(p));
    if (v < 16u) atomicAdd(hist.bin[v], 1u);
    float o = (interleave_offset(p) - 1.0 / 32.0) * 16.0;
    uint w = uint(o + 0.5);
    if (abs(o - float(w)) < 1e-6 && w < 16u) atomicAdd(hist.bin[16u + w], 1u);
}
