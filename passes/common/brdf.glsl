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

// --- Microfacet terms ------------------------------------------------------------------------

// Beckmann distribution as printed in 000_c9f7e5de708ecbb3.txt L1150-1156 (m: RMS slope):
//     D = 1 / (4 m^2 (n.h)^4) * exp(((n.h)^2 - 1) / (m^2 (n.h)^2))
// With 4 m^2 the projected-area integral  integral D (n.h) d(omega_h)  is pi/4 for every m,
// not 1 (TECHNIQUES.md pitfall); ndf_beckmann below is the normalised form.
float ndf_beckmann_printed(float n_dot_h, float m) {
    float c2 = n_dot_h * n_dot_h;
    return exp((c2 - 1.0) / (m * m * c2)) / (4.0 * m * m * c2 * c2);
}

// Normalised Beckmann: pi m^2 in place of 4 m^2, so integral D (n.h) d(omega_h) = 1.
float ndf_beckmann(float n_dot_h, float m) {
    float c2 = n_dot_h * n_dot_h;
    return exp((c2 - 1.0) / (m * m * c2)) / (kPi * m * m * c2 * c2);
}

// GGX / Trowbridge-Reitz as written in 002_644d46bdce7e5305.txt L200-215: a = r^2 (r the
// perceptual roughness), d = (n.h a^2 - n.h) n.h + 1, D = a^2 / (pi d^2).
float ndf_ggx(float n_dot_h, float roughness) {
    float a = roughness * roughness, a2 = a * a;
    float d = (n_dot_h * a2 - n_dot_h) * n_dot_h + 1.0;
    return a2 / (kPi * d * d);
}

// Torrance-Sparrow geometric attenuation (000 L1170-1180):
//     G = min(1, 2 (n.h)(n.v)/(v.h), 2 (n.h)(n.l)/(v.h))
float g_torrance_sparrow(float n_dot_h, float n_dot_v, float n_dot_l, float v_dot_h) {
    return min(1.0, min(2.0 * n_dot_h * n_dot_v / v_dot_h, 2.0 * n_dot_h * n_dot_l / v_dot_h));
}

// 002 L230-260: the Smith forms it uses already contain 1/(4 (n.l)(n.v)) — "visibility"
// terms V, so f_spec = D F V with no further division (a pitfall TECHNIQUES.md notes).
// Smith-GGX, exact: V = 1 / (GV.x GV.y), GV = n.vl + sqrt((n.vl - n.vl a2) n.vl + a2).
float v_smith_ggx(float n_dot_v, float n_dot_l, float roughness) {
    float a = roughness * roughness, a2 = a * a;
    float gv = n_dot_v + sqrt((n_dot_v - n_dot_v * a2) * n_dot_v + a2);
    float gl = n_dot_l + sqrt((n_dot_l - n_dot_l * a2) * n_dot_l + a2);
    return 1.0 / (gv * gl);
}
// Schlick-GGX with k = r^2 / 2: V = 0.25 / ((n.v (1 - k) + k)(n.l (1 - k) + k)).
float v_schlick_ggx(float n_dot_v, float n_dot_l, float roughness) {
    float k = roughness * roughness * 0.5;
    return 0.25 / ((n_dot_v * (1.0 - k) + k) * (n_dot_l * (1.0 - k) + k));
}

#endif
