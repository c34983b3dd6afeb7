// EXERCISE (shading/brdf-lab: TODO 4 below; this copy shadows passes/shading/brdf_catalog.glsl
// for that preset only).
// Every BRDF of passes/common/brdf.glsl as one function f_r(l, v) of two unit directions in
// the local frame n = +z, tangent t = +x, bitangent b = +y, so a tabulation, an albedo
// integral or a reciprocity test can loop over all of them (shading/brdf-lab, shading/phong,
// shading/oren-nayar, shading/anisotropic-ashikhmin-shirley).
// Specular colours and albedos are 1 (c_d = c_s = rho = 1); Fresnel, where a model has one,
// is Schlick's with F0 = p.y (passes/common/fresnel.glsl). Below the horizon f_r = 0.
#ifndef PASSLAB_BRDF_CATALOG_GLSL
#define PASSLAB_BRDF_CATALOG_GLSL
#include "common/brdf.glsl"
#include "common/fresnel.glsl"

// kind                            p.x                    p.y
#define BRDF_LAMBERT             0  // -                  -      1/pi                       (000 L881-899)
#define BRDF_PHONG               1  // m                  -      (v.r)^m                    (000 L912-926)
#define BRDF_BLINN               2  // m                  -      (n.h)^m                    (000 L980-988)
#define BRDF_BLINN_NORMALIZED    3  // m                  -      (m+8)/(8pi) (n.h)^m        (000 L1008-1011)
#define BRDF_COOK_TORRANCE_PRINTED 4  // RMS slope m      F0     D_4m^2 F G / (4 nl nv)     (000 D L1163-1173, G L1189-1201, f L1213-1217)
#define BRDF_COOK_TORRANCE       5  // RMS slope m        F0     D_pi m^2 F G / (4 nl nv)
#define BRDF_GGX_SMITH           6  // roughness r        F0     D_GGX F V_Smith            (002 D L157-166, V L231-239)
#define BRDF_GGX_SCHLICK         7  // roughness r        F0     D_GGX F V_Schlick-GGX      (002 V L243-249)
#define BRDF_OREN_NAYAR          8  // sigma (radians)    -      Oren-Nayar 1994            (000 L1273-1294)
#define BRDF_ASHIKHMIN_SHIRLEY   9  // e_u (along t)      e_v    specular lobe, R_s = 1     (000 L1258-1265)
// Not a BRDF, kept to show what the tests catch: the printed Phong shader's specular as
// reflected radiance per unit irradiance, (v.r)^m / (n.l) (000 L1371: no cos(theta_i)).
#define BRDF_PHONG_PRINTED_SHADER 10 // m                 -

float brdf_catalog(int kind, vec3 l, vec3 v, vec2 p) {
    const vec3 n = vec3(0.0, 0.0, 1.0), t = vec3(1.0, 0.0, 0.0), b = vec3(0.0, 1.0, 0.0);
    float nl = l.z, nv = v.z;
    if (nl <= 0.0 || nv <= 0.0) return 0.0;
    // TODO 4: the half vector h between l and v (000_c9f7e5de708ecbb3.txt L1018-1020, L1157-1159): the
    // direction halfway between the two, on which (n.h)^m and every microfacet term here
    // depend (nh is its cosine to the normal, vh its cosine to v). What length must it have?
    vec3 h = vec3(0.0, 0.0, 1.0);
    float nh = clamp(h.z, 0.0, 1.0);
    float vh = clamp(dot(v, h), 0.0, 1.0);  // clamped: Schlick's pow(1 - vh, 5) of a negative is undefined
    if (kind == BRDF_LAMBERT) return brdf_lambert(vec3(1.0)).x;
    if (kind == BRDF_PHONG) return phong_lobe(v, phong_mirror(n, l), p.x);
    if (kind == BRDF_BLINN) return blinn_phong_lobe(n, h, p.x);
    if (kind == BRDF_BLINN_NORMALIZED) return blinn_phong_normalized(n, h, p.x);
    if (kind == BRDF_COOK_TORRANCE_PRINTED || kind == BRDF_COOK_TORRANCE) {
        float D = kind == BRDF_COOK_TORRANCE ? ndf_beckmann(nh, p.x) : ndf_beckmann_printed(nh, p.x);
        float G = g_torrance_sparrow(nh, nv, nl, max(vh, 1e-7));
        return D * fresnel_schlick(vh, p.y) * G / (4.0 * nv * nl);
    }
    if (kind == BRDF_GGX_SMITH || kind == BRDF_GGX_SCHLICK) {
        // 002 L231-249: the visibility terms already hold 1/(4 n.l n.v): f = D F V.
        float V = kind == BRDF_GGX_SMITH ? v_smith_ggx(nv, nl, p.x) : v_schlick_ggx(nv, nl, p.x);
        return ndf_ggx(nh, p.x) * fresnel_schlick(vh, p.y) * V;
    }
    if (kind == BRDF_OREN_NAYAR) return brdf_oren_nayar(vec3(1.0), n, l, v, p.x).x;
    if (kind == BRDF_ASHIKHMIN_SHIRLEY) return ashikhmin_shirley_spec(n, t, b, l, v, p.x, p.y, 1.0);
    if (kind == BRDF_PHONG_PRINTED_SHADER) return phong_lobe(v, phong_mirror(n, l), p.x) / nl;
    return 0.0;
}

// Direction with polar angle theta from n = +z and azimuth phi from t = +x.
vec3 brdf_dir(float theta, float phi) {
    return vec3(sin(theta) * cos(phi), sin(theta) * sin(phi), cos(theta));
}
#endif
