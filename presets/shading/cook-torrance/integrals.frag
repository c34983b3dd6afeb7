#version 450
// integral over the hemisphere of D(theta) cos(theta) d(omega) = 2 pi integral_0^(pi/2) D cos sin d(theta),
// by the midpoint rule with 256 x 256 steps (nested: lavapipe cuts single loops at 65535).
#include "common/brdf.glsl"
layout(location = 0) out float integrals;
const float kSlopes[3] = float[](0.069, 0.24, 0.5);
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float m = kSlopes[p.x];
    const int kSteps = 256;
    const float dt = 0.5 * kPi / float(kSteps * kSteps);
    float sum = 0.0;
    for (int i = 0; i < kSteps; ++i)
        for (int j = 0; j < kSteps; ++j) {
            float theta = (float(i * kSteps + j) + 0.5) * dt, c = cos(theta);
            float D = p.y == 0 ? ndf_beckmann_printed(c, m) : ndf_beckmann(c, m);
            sum += D * c * sin(theta);
        }
    integrals = 2.0 * kPi * sum * dt;
}
