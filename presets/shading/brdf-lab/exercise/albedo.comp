#version 450
// EXERCISE — the BRDF lab's energy integral. TODO 1 and 2 here, TODO 3 in table.comp, TODO 4 in
// shading/brdf_catalog.glsl. Check your work against the reference:
//     passlab run   shading/brdf-lab --exercise presets/shading/brdf-lab/exercise
//     passlab grade shading/brdf-lab --exercise presets/shading/brdf-lab/exercise
// Directional albedo (the energy a BRDF reflects towards v from a uniform white sky),
//     a(theta_o) = integral over the hemisphere of f_r(l, v) cos(theta_l) d(omega_l)
// for v at theta_o = 5 deg * x (azimuth 0), entry y. Energy conservation asks a <= 1
// (000_c9f7e5de708ecbb3.txt L822-824 and L5004-5005 print the integral without the
// cos(theta_i): as printed, Lambert's 1/pi would integrate to 2, so the cosine is meant, once:
// the rendering equation L4979 weighs incoming light by it).
// The integral is written in spherical coordinates (theta, phi) of l and summed with Simpson's
// rule in theta (64 intervals, weights given) and the midpoint rule in phi (128 steps).
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
    // TODO 1: sum f_r(l, v) (entry_brdf(e, l, v)) over the kPhi directions l of this row: polar
    // angle theta, azimuths at the midpoints of kPhi equal steps dp (brdf_dir(theta, phi) in
    // shading/brdf_catalog.glsl turns angles into a unit vector).
    // TODO 2: the row's share of the integral: sum times the quadrature weights (weight in
    // theta, dp in phi) times what else? The integrand of a(theta_o) is f_r cos(theta); and
    // d(omega) in spherical coordinates is not d(theta) d(phi).
    partial[row] = sum * weight * dp;
    barrier();
    for (int s = kTheta / 2; s > 0; s /= 2) {
        if (row < s) partial[row] += partial[row + s];
        barrier();
    }
    if (row == 0) imageStore(albedo, ivec2(x, e), vec4(partial[0]));
}
