// The split-sum BRDF integration of 002_644d46bdce7e5305.txt L312-417 (Karis 2013):
//   (1/N) sum f cos / p = F0 * LUT.r + LUT.g
// integrated by importance-sampling GGX with Hammersley points, n = (0, 0, 1), v in the xz
// plane. Fixes to the listing (docs/catalogue.md pitfalls): its #ifndef GL4_AND_UP guard (L353) is
// inverted (the bit-twiddling branch runs where bitfieldReverse exists); its `ul` literals
// (L358-361) are not GLSL; the loop calls specularG2 (L411) but the function is specularG (L387). G here is the Smith-GGX
// visibility form (it holds 1/(4 n.l n.v)), hence the 4 v.h / n.h factor and no other.
#ifndef PASSLAB_BRDF_LUT_GLSL
#define PASSLAB_BRDF_LUT_GLSL
#include "common/brdf.glsl"

vec2 hammersley(int i, int n) { return vec2(fract(float(i) / float(n)), float(bitfieldReverse(uint(i))) * 2.3283064365386963e-10); }

// GGX half vector for uniform e in [0,1)^2 (m = r^2): cos(theta) = sqrt((1 - e.y) / (1 + (m^2 - 1) e.y)).
vec3 importance_sample_ggx(vec2 e, float roughness) {
    float m = roughness * roughness, m2 = m * m;
    float phi = 2.0 * kPi * e.x;
    float cos_t = sqrt((1.0 - e.y) / (1.0 + (m2 - 1.0) * e.y)), sin_t = sqrt(1.0 - cos_t * cos_t);
    return vec3(sin_t * cos(phi), sin_t * sin(phi), cos_t);
}

vec2 integrate_brdf(float roughness, float n_dot_v, int samples) {
    vec3 V = vec3(sqrt(1.0 - n_dot_v * n_dot_v), 0.0, n_dot_v);
    vec2 r = vec2(0.0);
    for (int i = 0; i < samples; ++i) {
        vec3 H = importance_sample_ggx(hammersley(i, samples), roughness);
        vec3 L = -reflect(V, H);
        float n_dot_l = clamp(L.z, 0.0, 1.0);
        if (n_dot_l > 0.0) {
            float v_dot_h = clamp(dot(V, H), 0.0, 1.0);
            // Schlick-GGX visibility, k = (r + 1)^2 / 8
            float k = (roughness + 1.0) * (roughness + 1.0) / 8.0, nv = max(n_dot_v, 1e-5);
            float G = 0.25 / ((nv * (1.0 - k) + k) * (n_dot_l * (1.0 - k) + k));
            r += (vec2(1.0, 0.0) + vec2(-1.0, 1.0) * pow(1.0 - v_dot_h, 5.0)) * (n_dot_l * G * (4.0 * v_dot_h) / clamp(H.z, 1e-6, 1.0));
        }
    }
    return r / float(samples);
}
#endif
