// EXERCISE — the split-sum BRDF integration of 002_644d46bdce7e5305.txt L312-417 (Karis 2013):
//   (1/N) sum f(l_k, v) cos(theta_l) / p(l_k, v)  =  F0 * LUT.r + LUT.g
// integrated by importance-sampling GGX with Hammersley points, n = (0, 0, 1), v in the xz
// plane. This file shadows passes/envmap/brdf_lut.glsl (lut.frag and points.frag include it).
//     passlab run   envmap/ibl-brdf-lut --exercise presets/envmap/ibl-brdf-lut/exercise
//     passlab grade envmap/ibl-brdf-lut --exercise presets/envmap/ibl-brdf-lut/exercise
// The helpers you need are in passes/common/brdf.glsl: kPi, and the geometry term of 002 L386-392
// (specularG, Smith-GGX) as v_smith_ggx(n.v, n.l, roughness). It is a VISIBILITY term,
// G / (4 n.l n.v): the 1/(4 n.l n.v) of the microfacet BRDF is already inside it (002 L228-250).
#ifndef PASSLAB_BRDF_LUT_GLSL
#define PASSLAB_BRDF_LUT_GLSL
#include "common/brdf.glsl"

// 002 L351-371 (with the fixes of the README: no `ul` literals, bitfieldReverse exists).
vec2 hammersley(int i, int n) { return vec2(fract(float(i) / float(n)), float(bitfieldReverse(uint(i))) * 2.3283064365386963e-10); }

// GGX half vector for the uniform point e in [0,1)^2 (002 L377-384).
vec3 importance_sample_ggx(vec2 e, float roughness) {
    // TODO 1: the GGX importance sample of the half vector: azimuth phi = 2 pi e.x, and the polar
    // angle from inverting the GGX distribution's CDF (002 L381),
    //     cos(theta) = sqrt((1 - e.y) / (1 + (m^2 - 1) e.y)),
    // where m is GGX's alpha, which is NOT the artist's roughness itself (002 L378: how is it made
    // from roughness?). Return the unit half vector about n = z.
    return vec3(0.0, 0.0, 1.0);
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
            // TODO 2: this sample's f cos / p (002 L399-416), split into a scale and a bias on
            // F0. Schlick's Fresnel F = F0 + (1 - F0) Fc with Fc = (1 - v.h)^5 is F0 (1 - Fc) + Fc:
            // the part that multiplies F0 goes to r.x, the rest to r.y. The rest of f cos / p,
            // for half vectors drawn with GGX's pdf D n.h and turned into light directions
            // (pdf / (4 v.h)), is n.l times the visibility (use max(n_dot_v, 1e-5) in it) times
            // the Jacobian's 4 v.h / n.h (clamp n.h to [1e-6, 1]). D cancels.
        }
    }
    return r / float(samples);
}
#endif
