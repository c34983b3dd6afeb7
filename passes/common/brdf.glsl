// BRDFs shared by the shading presets. Conventions: n, l, v unit vectors pointing away from
// the surface; the functions return f_r (per steradian), so reflected radiance from a light of
// irradiance E is f_r * E * max(n.l, 0), and energy conservation means
// integral over the hemisphere of f_r cos(theta_i) d(omega_i) <= 1.
#ifndef PASSLAB_BRDF_GLSL
#define PASSLAB_BRDF_GLSL

const float kPi = 3.14159265358979;

// Lambert (000_c9f7e5de708ecbb3.txt L881-899, L1008-1011): f_r = c_d / pi. The 1/pi makes the
// hemisphere integral of f_r cos(theta) exactly c_d: an albedo of 1 reflects all it receives.
vec3 brdf_lambert(vec3 albedo) { return albedo / kPi; }

// Normalised Blinn-Phong specular lobe (000_c9f7e5de708ecbb3.txt L1008-1011, 002 L48-78):
//     f_spec = (m + 8) / (8 pi) * c_s * (n.h)^m,   h = normalize(v + l)
// The factor keeps the lobe's energy roughly constant as m grows; it is an approximation (the
// directional albedo at normal view is 1.024, 1.075, 1.027, 1.004 for m = 1, 8, 64, 512).
float blinn_phong_normalized(vec3 n, vec3 h, float m) {
    return (m + 8.0) / (8.0 * kPi) * pow(max(dot(n, h), 0.0), m);
}

#endif
