#version 450
// Chi-square distance between the luminance histograms (16 bins) of `subject` and `source`:
// chi2 = 1/2 sum_k (p_k - q_k)^2 / (p_k + q_k), with p, q the normalised histograms; 0 for
// equal histograms, 1 for disjoint ones. One work group; written to stats.value[0].
#include "common/color.glsl"

layout(local_size_x = 256) in;
uniform sampler2D subject;
uniform sampler2D source;
layout(std430) buffer Stats { float value[]; } stats;

shared uint bins_p[16];
shared uint bins_q[16];

uint bin_of(vec3 c) { return min(uint(luminance(c) * 16.0), 15u); }

void main() {
    uint t = gl_LocalInvocationIndex;
    if (t < 16u) { bins_p[t] = 0u; bins_q[t] = 0u; }
    barrier();
    ivec2 sp = textureSize(subject, 0), sq = textureSize(source, 0);
    for (int i = int(t); i < sp.x * sp.y; i += 256)
        atomicAdd(bins_p[bin_of(texelFetch(subject, ivec2(i % sp.x, i / sp.x), 0).rgb)], 1u);
    for (int i = int(t); i < sq.x * sq.y; i += 256)
        atomicAdd(bins_q[bin_of(texelFetch(source, ivec2(i % sq.x, i / sq.x), 0).rgb)], 1u);
    barrier();
    if (t == 0u) {
        float chi2 = 0.0;
        for (int k = 0; k < 16; ++k) {
            float p = float(bins_p[k]) / float(sp.x * sp.y), q = float(bins_q[k]) / float(sq.x * sq.y);
            if (p + q > 0.0) chi2 += 0.5 * (p - q) * (p - q) / (p + q);
        }
        stats.value[0] = chi2;
    }
}
