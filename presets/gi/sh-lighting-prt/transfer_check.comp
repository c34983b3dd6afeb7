#version 450
// Test-only (params.verify): the unshadowed transfer against the analytic one. With V = 1,
// T_k(n) = (1/pi) integral max(n.w, 0) y_k(w) dw = (A_l / pi) y_k(n) (Funk-Hecke: the clamped
// cosine is zonal about n, so it scales band l by A_l, Ramamoorthi and Hanrahan 2001):
// A_0 / pi = 1, A_1 / pi = 2/3, A_2 / pi = 1/4, A_3 / pi = 0. Writes the largest error of each
// band over all vertices into `transfer_error[l]` (float bits through atomicMax: non-negative
// floats order as their bits).
layout(local_size_x = 64) in;
layout(std430) readonly buffer Verts { vec4 v[]; } verts;
layout(std430) readonly buffer Transfer { float t[]; } transfer;
layout(std430) buffer TransferError { uint band[4]; } transfer_error;
#include "gi/sh.glsl"
#include "env.glsl"

void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= 2u * PRT_CAPACITY) return;
    vec3 n = verts.v[2u * i + 1u].xyz;
    if (dot(n, n) < 0.25) return;
    const float a_over_pi[4] = float[](1.0, 2.0 / 3.0, 0.25, 0.0);
    float y[16];
    sh_eval(n, 4, y);
    for (int l = 0; l < 4; ++l) {
        float e = 0.0;
        for (int m = -l; m <= l; ++m) {
            int k = sh_index(l, m);
            e = max(e, abs(transfer.t[16u * i + uint(k)] - a_over_pi[l] * y[k]));
        }
        atomicMax(transfer_error.band[l], floatBitsToUint(e));
    }
}
