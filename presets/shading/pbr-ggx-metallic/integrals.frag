#version 450
// 2 pi integral_0^(pi/2) D_GGX(cos theta) cos theta sin theta d(theta), midpoint rule, 256 x 256 steps.
#include "common/brdf.glsl"
layout(location = 0) out float integrals;
const float kRoughness[4] = float[](0.1, 0.3, 0.6, 1.0);
void main() {
    float r = kRoughness[int(gl_FragCoord.x)];
    const int kSteps = 256;
    const float dt = 0.5 * kPi / float(kSteps * kSteps);
    float sum = 0.0;
    for (int i = 0; i < kSteps; ++i)
        for (int j = 0; j < kSteps; ++j) {
            float theta = (float(i * kSteps + j) + 0.5) * dt, c = cos(theta);
            sum += ndf_ggx(c, r) * c * sin(theta);
        }
    integrals = 2.0 * kPi * sum * dt;
}
