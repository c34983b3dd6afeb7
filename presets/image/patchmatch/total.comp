#version 450
// Sum over A of d(a, f(a)) after this frame's iteration, into totals[iteration] (the last
// element for every later iteration). One work group, each thread summing a fixed stride of
// pixels, then a tree in shared memory: the order of additions is fixed, so the sum is
// deterministic, and since every d(a, f(a)) only ever decreases (a candidate replaces f(a)
// only when strictly closer) and rounding is monotone, the totals cannot increase.
#include "image/nnf.glsl"

layout(local_size_x = 256) in;
uniform sampler2D nnf_in;
layout(std430) buffer Totals { float total[]; } totals;

shared float partial[256];

void main() {
    ivec2 size = textureSize(nnf_in, 0);
    uint t = gl_LocalInvocationIndex;
    float s = 0.0;
    for (int i = int(t); i < size.x * size.y; i += 256)
        s += nnf_distance(texelFetch(nnf_in, ivec2(i % size.x, i / size.x), 0));
    partial[t] = s;
    barrier();
    for (uint k = 128u; k > 0u; k >>= 1) {
        if (t < k) partial[t] += partial[t + k];
        barrier();
    }
    if (t == 0u) totals.total[min(frame.accum_frame, totals.total.length() - 1)] = partial[0];
}
