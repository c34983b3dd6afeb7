#version 450
// Test-only: the Gaussian weights of shadow_map.glsl (the ones the view filters with) at 256
// sub-texel offsets in [0, 1) (n = params.kernel, sigma = params.sigma): buffer `weight_sums`
// element k = |sum_i w_i - 1| at offset k / 256. The 2D weights wx_i wy_j then sum to 1 as well.
layout(local_size_x = 64) in;
#include "shadows/shadow_map.glsl"
layout(std430) writeonly buffer WeightSums { float e[256]; } weight_sums;
void main() {
    uint k = gl_GlobalInvocationID.x;
    if (k >= 256u) return;
    float w[8];
    shadow_gauss_weights(float(k) / 256.0, params.kernel, params.sigma, w);
    float sum = 0.0;
    for (int i = 0; i < 8; ++i) sum += w[i];
    weight_sums.e[k] = abs(sum - 1.0);
}
