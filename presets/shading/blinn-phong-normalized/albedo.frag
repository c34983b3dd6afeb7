#version 450
// Directional albedo at normal view, a(m) = integral f_spec(l) cos(theta_l) d(omega_l) with
// v = n. The lobe is then symmetric about n, so the phi integral is 2 pi and
//     a(m) = 2 pi * integral_0^{pi/2} f(theta) cos(theta) sin(theta) d(theta),
// with n.h = cos(theta / 2). Midpoint rule with 8192 steps: converged to < 1e-4 for m <= 512.
#include "common/brdf.glsl"
layout(location = 0) out float albedo;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    const float normalized_m[4] = float[](1.0, 8.0, 64.0, 512.0);
    const float plain_m[4] = float[](100.0, 512.0, 1.0, 8.0);
    bool normalized = p.y == 0;
    float m = normalized ? normalized_m[p.x] : plain_m[p.x];
    const int steps = 8192;
    float dt = 0.5 * kPi / float(steps), sum = 0.0;
    for (int i = 0; i < steps; ++i) {
        float t = (float(i) + 0.5) * dt;
        // v = n = +z and l at angle t in the xz plane: h = (sin(t/2), 0, cos(t/2)). The lobes are
        // the shader's own (passes/common/brdf.glsl), so a wrong factor there fails this table.
        // Row 1 is the plain lobe (n.h)^m with c_s = 1, as the blinn model uses it.
        vec3 n = vec3(0.0, 0.0, 1.0), h = vec3(sin(0.5 * t), 0.0, cos(0.5 * t));
        float f = normalized ? blinn_phong_normalized(n, h, m) : blinn_phong_lobe(n, h, m);
        sum += f * cos(t) * sin(t);
    }
    albedo = 2.0 * kPi * sum * dt;
}
