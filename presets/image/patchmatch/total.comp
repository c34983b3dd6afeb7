#version 450
// Sum over A of d(a, f(a)) at the end of the frame, into totals[i] for the iteration i the
// frame's last sub-step belongs to (step.comp; the last element for every later iteration):
// after an iteration's last sub-step, the total of that iteration. One work group, each thread summing a fixed stride of
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
    int n = params.substeps / 2 * 2;   // sub-steps a frame, as the step pass's repeat
    int iteration = (frame.accum_frame * n + n - 1) / 8;
    if (t == 0u) totals.total[min(iteration, totals.total.length() - 1)] = partial[0];
}
