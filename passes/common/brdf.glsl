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

#endif
