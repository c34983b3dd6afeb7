// The BRDF lab's entries: every BRDF of passes/common/brdf.glsl (through
// passes/shading/brdf_catalog.glsl) with the slides' parameters (000_c9f7e5de708ecbb3.txt
// L1022-1060: theta_i = 30/60 deg, m = 8/100; L1175-1240: Beckmann m = 0.24/0.069).
// The last entry is the printed Phong shader's (v.r)^m / (n.l): not a BRDF (not reciprocal),
// plotted for comparison and left out of the reciprocity range check.
#include "shading/brdf_catalog.glsl"

const int kEntries = 14;
const int kPrintedEntry = 13;

// Table sampling: theta_i = 5 deg * i (i < 18), theta_o = 1 deg * o (o < 90), phi = 20 deg * p
// (p < 18); phi is v's azimuth, l lies at azimuth 0 (along the tangent), so phi = 180 deg is
// the mirror side of the plane of incidence and phi = 0 the side of the light.
const int kNi = 18, kNo = 90, kNp = 18;
const float kDegree = 0.0174532925199;
const float kStepI = 5.0, kStepO = 1.0, kStepP = 20.0;  // degrees

int entry_kind(int e) {
    const int kinds[kEntries] = int[](BRDF_LAMBERT, BRDF_PHONG, BRDF_PHONG, BRDF_BLINN, BRDF_BLINN,
        BRDF_BLINN_NORMALIZED, BRDF_COOK_TORRANCE_PRINTED, BRDF_COOK_TORRANCE, BRDF_COOK_TORRANCE,
        BRDF_GGX_SMITH, BRDF_GGX_SCHLICK, BRDF_OREN_NAYAR, BRDF_ASHIKHMIN_SHIRLEY,
        BRDF_PHONG_PRINTED_SHADER);
    return kinds[e];
}

vec2 entry_param(int e) {
    vec2 p[kEntries] = vec2[](vec2(0.0), vec2(params.m_a, 0.0), vec2(params.m_b, 0.0),
        vec2(params.m_a, 0.0), vec2(params.m_b, 0.0), vec2(params.m_a, 0.0),
        vec2(params.beckmann_a, params.f0), vec2(params.beckmann_a, params.f0),
        vec2(params.beckmann_b, params.f0), vec2(params.ggx_roughness, params.f0),
        vec2(params.ggx_roughness, params.f0), vec2(params.sigma, 0.0),
        vec2(params.as_u, params.as_v), vec2(params.m_a, 0.0));
    return p[e];
}

float entry_brdf(int e, vec3 l, vec3 v) { return brdf_catalog(entry_kind(e), l, v, entry_param(e)); }
