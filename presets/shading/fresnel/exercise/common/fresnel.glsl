// EXERCISE — Fresnel reflectance of a dielectric interface, three ways.
// This file shadows passes/common/fresnel.glsl for the shading/fresnel preset only: the curves,
// the end values and the sphere are all computed by the functions below.
//     passlab run   shading/fresnel --exercise presets/shading/fresnel/exercise   (live, hot reload)
//     passlab grade shading/fresnel --exercise presets/shading/fresnel/exercise   (the test cases)
// Each function returns a placeholder now; fill in the three TODO blocks.
#ifndef PASSLAB_FRESNEL_GLSL
#define PASSLAB_FRESNEL_GLSL

// The Fresnel equations as printed in 000_c9f7e5de708ecbb3.txt L1112-1118, for unpolarised light.
float fresnel_exact(float cos_i, float n1, float n2) {
    float sin_i = sqrt(max(0.0, 1.0 - cos_i * cos_i));
    // TODO 1: with cos_t = sqrt(1 - (n1/n2 sin(theta_i))^2), the square root in both fractions,
    //     R_s = |(n1 cos_i - n2 cos_t) / (n1 cos_i + n2 cos_t)|^2     (L1112)
    //     R_p = |(n1 cos_t - n2 cos_i) / (n1 cos_t + n2 cos_i)|^2     (L1114)
    //     R   = (R_s + R_p) / 2                                       (L1118)
    // The root's argument is negative when n1 > n2 beyond the critical angle: no light is
    // transmitted then (total internal reflection), so R = 1. Do not take the root of it.
    return 0.0;
}

// R0, the reflectance at normal incidence: the exact R at cos_i = 1.
float fresnel_f0(float n1, float n2) {
    // TODO 2a: put cos_i = cos_t = 1 into R_s (or R_p) above and simplify: R0 depends only on
    // n1 and n2 (for glass in air, 1 and 1.5, it is 0.04).
    return 0.0;
}

// Schlick 1994 (000 L1124-1126).
float fresnel_schlick(float cos_i, float f0) {
    // TODO 2b: R = R0 + (1 - R0)(1 - cos(theta_i))^5.
    return f0;
}

// Spherical-Gaussian form of Schlick (Lagarde 2012), as printed in 002_644d46bdce7e5305.txt
// L190-195 (specularF): Schlick's (1 - cos)^5 replaced by a power of two.
float fresnel_schlick_sg(float v_dot_h, float f0) {
    // TODO 3: fc = 2^((-5.55473 v.h - 6.98316) v.h)  (exp2 in GLSL), then F = fc + (1 - fc) F0.
    return f0;
}

#endif
