#version 450
// Smoothness across cell borders (004_9a40ad89bdfc582a.txt L355-356: q''(0) = q''(1) = 0 makes
// the noise C2, h leaves the second derivative discontinuous). At a border x = k the centred
// second difference just right of it and just left of it,
//     D2(x) = (n(x + e) - 2 n(x) + n(x - e)) / e^2,      J(e) = D2(k + e) - D2(k - e),
// uses points of one cell each. If n'' is continuous, J(e) = e (n'''(k+) + n'''(k-)) + O(e^2):
// halving e halves it. If n'' jumps (h), J(e) -> the jump: halving e leaves it. Pixel 0 writes
// sum |J(e)| / sum |J(2e)| over 256 border points (x = k, random y; borders along y are the
// same by symmetry): ~0.5 for q, ~1 for h. (A direct "jump < 1e-3 of the range" needs e so small
// that float rounding of D2, ~4 eps / e^2, swamps it: e = 1/64 is the smallest step where the
// rounding, ~1e-3, is far below J.)
#include "noise.glsl"
layout(location = 0) out float ratio;
float d2(vec2 p, float e) {
    return (gradient_noise_2d(p + vec2(e, 0.0)) - 2.0 * gradient_noise_2d(p) + gradient_noise_2d(p - vec2(e, 0.0))) / (e * e);
}
void main() {
    const float e = 1.0 / 64.0;
    float s1 = 0.0, s2 = 0.0;
    for (int i = 0; i < 256; ++i) {
        vec2 p = vec2(float(i % 16 + 3), float(i / 16 + 3) + fract(0.618034 * float(i) + 0.1));
        s1 += abs(d2(p + vec2(e, 0.0), e) - d2(p - vec2(e, 0.0), e));
        s2 += abs(d2(p + vec2(2.0 * e, 0.0), 2.0 * e) - d2(p - vec2(2.0 * e, 0.0), 2.0 * e));
    }
    ratio = s1 / s2;
}
