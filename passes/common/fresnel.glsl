// Fresnel reflectance of a dielectric interface, three ways.
#ifndef PASSLAB_FRESNEL_GLSL
#define PASSLAB_FRESNEL_GLSL

// The Fresnel equations as printed in 000_c9f7e5de708ecbb3.txt L1108-1118 (unpolarised light:
// R = (R_s + R_p) / 2). Total internal reflection (n1 > n2 beyond the critical angle) gives 1.
float fresnel_exact(float cos_i, float n1, float n2) {
    float sin_i = sqrt(max(0.0, 1.0 - cos_i * cos_i));
    float k = 1.0 - (n1 / n2 * sin_i) * (n1 / n2 * sin_i);
    if (k <= 0.0) return 1.0;
    float cos_t = sqrt(k);
    float rs = (n1 * cos_i - n2 * cos_t) / (n1 * cos_i + n2 * cos_t);
    float rp = (n1 * cos_t - n2 * cos_i) / (n1 * cos_t + n2 * cos_i);
    return 0.5 * (rs * rs + rp * rp);
}

// R0 = ((n1 - n2) / (n1 + n2))^2: the reflectance at normal incidence.
float fresnel_f0(float n1, float n2) {
    float r = (n1 - n2) / (n1 + n2);
    return r * r;
}

// Schlick 1994 (000 L1122-1130): R(theta) = R0 + (1 - R0)(1 - cos theta)^5.
float fresnel_schlick(float cos_i, float f0) { return f0 + (1.0 - f0) * pow(1.0 - cos_i, 5.0); }

// Spherical-Gaussian form of Schlick (Lagarde 2012, as in 002_644d46bdce7e5305.txt L185-196):
// fc = 2^((-5.55473 v.h - 6.98316) v.h),  F = fc + (1 - fc) F0.
float fresnel_schlick_sg(float v_dot_h, float f0) {
    float fc = exp2((-5.55473 * v_dot_h - 6.98316) * v_dot_h);
    return fc + (1.0 - fc) * f0;
}

#endif
