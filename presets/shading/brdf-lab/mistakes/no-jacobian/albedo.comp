#version 450
// Directional albedo (the energy a BRDF reflects towards v from a uniform white sky),
//     a(theta_o) = integral over the hemisphere of f_r(l, v) cos(theta_l) d(omega_l)
//               = int_0^{pi/2} int_0^{2 pi} f_r cos(theta_l) sin(theta_l) d(phi) d(theta)
// for v at theta_o = 5 deg * x (azimuth 0), entry y. Energy conservation asks a <= 1
// (000_c9f7e5de708ecbb3.txt L822-824 and L5004-5005 print the integral without the
// cos(theta_i): as printed, Lambert's 1/pi would integrate to 2, so the cosine is meant).
// Simpson's rule in theta (64 intervals; the rows at theta = 0 and 90 deg contribute 0, sin and
// cos vanish there), the midpoint rule in phi (128 steps; periodic, so it converges fast).
// Simpson and not the midpoint rule in theta: the midpoint rule's error (h^2/24)(g'(pi/2) -
// g'(0)) is 2 pi h^2 f(n) / 24 at the pole, 0.3% for the Beckmann m = 0.069 lobe at v = n.
// One work group per (theta_o, entry), one theta row per thread, a shared-memory sum.
#include "entries.glsl"
layout(local_size_x = 64) in;
layout(r32f) uniform writeonly image2D albedo;
const int kTheta = 64, kPhi = 128;
shared float partial[kTheta];

void main() {
    int x = int(gl_WorkGroupID.x), e = int(gl_WorkGroupID.y), row = int(gl_LocalInvocationID.x);
    vec3 v = brdf_dir(5.0 * float(x) * kDegree, 0.0);
    const float dt = 0.5 * kPi / float(kTheta), dp = 2.0 * kPi / float(kPhi);
    float theta = float(row) * dt, sum = 0.0;
    float weight = (row % 2 == 1 ? 4.0 : 2.0) * dt / 3.0;   // Simpson: 1 4 2 4 ... 2 4 1
    for (int j = 0; j < kPhi; ++j) {
        vec3 l = brdf_dir(theta, (float(j) + 0.5) * dp);
        sum += entry_brdf(e, l, v);
    }
    partial[row] = sum * cos(theta) * weight * dp;
    barrier();
    for (int s = kTheta / 2; s > 0; s /= 2) {
        if (row < s) partial[row] += partial[row + s];
        barrier();
    }
    if (row == 0) imageStore(albedo, ivec2(x, e), vec4(partial[0]));
}
