#version 450
// Test pass: integrates the library's phase functions over the sphere, numerically,
//     integral P d omega = 2 pi integral_{-1}^{1} P(mu) d mu,
// Simpson's rule over 4096 intervals in mu (partial sums per block keep the float rounding
// below 1e-6), for g = 0, 0.5, 0.76, 0.9 (the columns of a 4x2 image):
//   row 0: (integral P_R, integral P_M(g), P_M(1, g), P_M(-1, g))  -> both integrals 1 +- 1e-3
//   row 1: 1 where P_M peaks towards the sun (P_M(1) > P_M(-1); for g = 0 the two are equal),
//          the same for the library's own g in .y, else 0
// It calls atmo_phase_rayleigh / atmo_phase_mie, the functions atmo_scatter applies.
#include "volumetric/atmosphere.glsl"
layout(location = 0) out vec4 color;
void main() {
    ivec2 px = ivec2(gl_FragCoord.xy);
    const float gs[4] = float[](0.0, 0.5, 0.76, 0.9);
    float g = gs[px.x];
    if (px.y == 0) {
        // Simpson's rule, 64 x 64 intervals (error ~h^4: 3e-6 for g = 0.9's narrow peak).
        // Not one loop of 65536 samples: llvmpipe ends any shader loop after 65535 iterations
        // (gallivm's loop limiter), which silently dropped the last 4 of 256 blocks (0.988).
        const int N = 64;
        const float h = 2.0 / float(N * N);
        precise float sumR = atmo_phase_rayleigh(-1.0) + atmo_phase_rayleigh(1.0);
        precise float sumM = atmo_phase_mie(-1.0, g) + atmo_phase_mie(1.0, g);
        for (int i = 0; i < N; i++) {
            precise float blockR = 0.0, blockM = 0.0;
            for (int j = 0; j < N; j++) {
                int k = i * N + j;
                if (k == 0) continue;
                float w = (k % 2 == 1) ? 4.0 : 2.0;
                float mu = -1.0 + float(k) * h;
                blockR += w * atmo_phase_rayleigh(mu);
                blockM += w * atmo_phase_mie(mu, g);
            }
            sumR += blockR;
            sumM += blockM;
        }
        sumR *= h / 3.0;
        sumM *= h / 3.0;
        color = vec4(2.0 * ATMO_PI * sumR, 2.0 * ATMO_PI * sumM, atmo_phase_mie(1.0, g), atmo_phase_mie(-1.0, g));
    } else {
        float fwd = atmo_phase_mie(1.0, g), back = atmo_phase_mie(-1.0, g);
        float peaks = g == 0.0 ? (fwd == back ? 1.0 : 0.0) : (fwd > back ? 1.0 : 0.0);
        float own = atmo_phase_mie(1.0, ATMO_G) > atmo_phase_mie(-1.0, ATMO_G) ? 1.0 : 0.0;
        color = vec4(peaks, own, 0.0, 1.0);
    }
}
