#version 450
// Lambert vs Oren-Nayar (000_c9f7e5de708ecbb3.txt L1273-1294: "deep cavities on the surface
// reflect light back to the light source; brighter at steep angles (near the silhouette)";
// the slides name the model and show pottery, no formula). OREN_NAYAR = 1 shades with the
// qualitative model of Oren & Nayar 1994 (passes/common/brdf.glsl, brdf_oren_nayar):
//     f_r = rho/pi (A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta)),
//     A = 1 - 0.5 s^2/(s^2 + 0.33),  B = 0.45 s^2/(s^2 + 0.09),
//     alpha = max(theta_i, theta_o),  beta = min(theta_i, theta_o)
// OREN_NAYAR = 0 with Lambert's f_r = rho/pi (000 L881-899). Both: L_o = f_r E cos(theta_i), E
// the irradiance of a light perpendicular to it, given as pi E_0 so that Lambert reads
// rho E_0 cos(theta_i) (the slides' L_o = c_d max(n.l, 0) I_L, L895).
#include "common/brdf.glsl"
#include "shading/eye_dir.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;

void main() {
    vec3 n = normalize(v_normal), v = eye_dir(v_world), l = normalize(params.light_dir);
    float cos_i = max(dot(n, l), 0.0);
#if OREN_NAYAR
    vec3 f = brdf_oren_nayar(params.albedo, n, l, v, params.sigma);
#else
    vec3 f = brdf_lambert(params.albedo);
#endif
    hdr = vec4(f * kPi * params.light * cos_i, 1.0);
}
