// BRDFs shared by the shading presets. Conventions: n, l, v unit vectors pointing away from
// the surface; the functions return f_r (per steradian), so reflected radiance from a light of
// irradiance E is f_r * E * max(n.l, 0), and energy conservation means
// integral over the hemisphere of f_r cos(theta_i) d(omega_i) <= 1.
#ifndef PASSLAB_BRDF_GLSL
#define PASSLAB_BRDF_GLSL

const float kPi = 3.14159265358979;

// Lambert (000_c9f7e5de708ecbb3.txt L881-898, L1011): f_r = c_d / pi. The 1/pi makes the
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

// Beckmann distribution as printed in 000_c9f7e5de708ecbb3.txt L1163-1173 (m: RMS slope):
//     D = 1 / (4 m^2 (n.h)^4) * exp(((n.h)^2 - 1) / (m^2 (n.h)^2))
// With 4 m^2 the projected-area integral  integral D (n.h) d(omega_h)  is pi/4 for every m,
// not 1 (docs/catalogue.md pitfall); ndf_beckmann below is the normalised form.
float ndf_beckmann_printed(float n_dot_h, float m) {
    float c2 = n_dot_h * n_dot_h;
    return exp((c2 - 1.0) / (m * m * c2)) / (4.0 * m * m * c2 * c2);
}

// Normalised Beckmann: pi m^2 in place of 4 m^2, so integral D (n.h) d(omega_h) = 1.
float ndf_beckmann(float n_dot_h, float m) {
    float c2 = n_dot_h * n_dot_h;
    return exp((c2 - 1.0) / (m * m * c2)) / (kPi * m * m * c2 * c2);
}

// GGX / Trowbridge-Reitz as written in 002_644d46bdce7e5305.txt L156-165: a = r^2 (r the
// perceptual roughness), d = (n.h a^2 - n.h) n.h + 1, D = a^2 / (pi d^2).
float ndf_ggx(float n_dot_h, float roughness) {
    float a = roughness * roughness, a2 = a * a;
    float d = (n_dot_h * a2 - n_dot_h) * n_dot_h + 1.0;
    return a2 / (kPi * d * d);
}

// Torrance-Sparrow geometric attenuation (000 L1189-1201):
//     G = min(1, 2 (n.h)(n.v)/(v.h), 2 (n.h)(n.l)/(v.h))
float g_torrance_sparrow(float n_dot_h, float n_dot_v, float n_dot_l, float v_dot_h) {
    return min(1.0, min(2.0 * n_dot_h * n_dot_v / v_dot_h, 2.0 * n_dot_h * n_dot_l / v_dot_h));
}

// 002 L228-250: the Smith forms it uses already contain 1/(4 (n.l)(n.v)) — "visibility"
// terms V, so f_spec = D F V with no further division (a pitfall docs/catalogue.md notes).
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

// --- Phong and Blinn-Phong lobes (appended for shading/phong and shading/brdf-lab) ------------

// Mirror direction as printed in 000_c9f7e5de708ecbb3.txt L926/L932 and L1368:
//     r = 2 n (n.l) - l        (l towards the light, all vectors normalised; = reflect(-l, n))
vec3 phong_mirror(vec3 n, vec3 l) { return 2.0 * n * dot(n, l) - l; }

// Phong's specular factor (000 L914, shader L1371): (cos alpha_r)^m = max(v.r, 0)^m.
// The printed model uses it as reflected radiance per unit light colour, L_o = c_s (v.r)^m B_L,
// without a cos(theta_i): as a BRDF that is (v.r)^m / (n.l), which is not reciprocal. The lobe
// itself is symmetric in l and v, because v.r = 2 (n.v)(n.l) - v.l.
float phong_lobe(vec3 v, vec3 r, float m) { return pow(max(dot(v, r), 0.0), m); }

// Blinn-Phong's unnormalised factor (000 L980-988): (cos theta_h)^m = max(n.h, 0)^m,
// h = normalize(v + l) (L1020).
float blinn_phong_lobe(vec3 n, vec3 h, float m) { return pow(max(dot(n, h), 0.0), m); }

// --- Oren-Nayar and Ashikhmin-Shirley (appended for shading/oren-nayar, -anisotropic-...) -----
// The course names both without a formula (000_c9f7e5de708ecbb3.txt L1258-1265, L1273-1294);
// the forms below are the original papers'.

// Oren & Nayar 1994, "Generalization of Lambert's reflectance model", the qualitative model
// (their eq. 30, without the interreflection term): V-cavity facets with slope-angle standard
// deviation sigma (radians) scatter light back towards the source (retro-reflection, L1275):
//     f_r = rho / pi (A + B max(0, cos(phi_i - phi_o)) sin(alpha) tan(beta))
//     A = 1 - 0.5 sigma^2 / (sigma^2 + 0.33),   B = 0.45 sigma^2 / (sigma^2 + 0.09)
//     alpha = max(theta_i, theta_o),            beta = min(theta_i, theta_o)
// sigma = 0 gives A = 1, B = 0: Lambert exactly. Symmetric in l and v (max/min, the cosine of
// the azimuth difference), so reciprocal. cos(phi_i - phi_o) from the tangent-plane
// projections of l and v; when either is along n, sin(alpha) tan(beta) = 0 anyway.
vec3 brdf_oren_nayar(vec3 albedo, vec3 n, vec3 l, vec3 v, float sigma) {
    float nl = clamp(dot(n, l), 0.0, 1.0), nv = clamp(dot(n, v), 0.0, 1.0);
    float s2 = sigma * sigma;
    float A = 1.0 - 0.5 * s2 / (s2 + 0.33), B = 0.45 * s2 / (s2 + 0.09);
    vec3 lp = l - n * nl, vp = v - n * nv;                        // tangent-plane projections
    float len2 = dot(lp, lp) * dot(vp, vp);
    float cos_phi = len2 > 1e-12 ? dot(lp, vp) * inversesqrt(len2) : 0.0;
    float cos_alpha = min(nl, nv), cos_beta = max(nl, nv);      // alpha = max angle, beta = min
    float sin_alpha = sqrt(max(0.0, 1.0 - cos_alpha * cos_alpha));
    float tan_beta = sqrt(max(0.0, 1.0 - cos_beta * cos_beta)) / max(cos_beta, 1e-7);
    return albedo / kPi * (A + B * max(0.0, cos_phi) * sin_alpha * tan_beta);
}

// Ashikhmin & Shirley 2000, "An anisotropic Phong BRDF model" (the course's brushed-metal
// example, 000 L1258-1265, n_v = 10): exponents e_u along the tangent t, e_v along the
// bitangent b (the paper's n_u, n_v), R_s the specular reflectance at normal incidence.
//     f_spec = sqrt((e_u + 1)(e_v + 1)) / (8 pi)
//              * (n.h)^((e_u (h.t)^2 + e_v (h.b)^2) / (1 - (n.h)^2))
//              / ((h.l) max(n.l, n.v)) * F(h.l),      F = R_s + (1 - R_s)(1 - h.l)^5
// 1 - (n.h)^2 = (h.t)^2 + (h.b)^2 for a unit h in the frame (t, b, n); that form is used for the
// exponent so it stays finite at h = n (the limit is then pow(1, e) = 1 for any e).
float ashikhmin_shirley_spec(vec3 n, vec3 t, vec3 b, vec3 l, vec3 v, float e_u, float e_v, float r_s) {
    float nl = dot(n, l), nv = dot(n, v);
    if (nl <= 0.0 || nv <= 0.0) return 0.0;
    vec3 h = normalize(l + v);
    float nh = clamp(dot(n, h), 0.0, 1.0), ht = dot(h, t), hb = dot(h, b);
    // h.l = |l + v| / 2 for unit l, v (h = (l + v)/|l + v|, so h.l = (1 + l.v)/|l + v|). That
    // form is symmetric in l and v to the last bit; dot(h, l) and dot(h, v) differ by rounding,
    // which near grazing (h.l ~ 0.03, from cancelling terms) reaches 1e-5 of f.
    float hl = clamp(0.5 * length(l + v), 0.0, 1.0);
    float sin2 = ht * ht + hb * hb;
    float e = sin2 > 1e-20 ? (e_u * ht * ht + e_v * hb * hb) / sin2 : 0.5 * (e_u + e_v);
    float fresnel = r_s + (1.0 - r_s) * pow(1.0 - hl, 5.0);
    return sqrt((e_u + 1.0) * (e_v + 1.0)) / (8.0 * kPi) * pow(nh, e) / (max(hl, 1e-7) * max(nl, nv)) * fresnel;
}

// Its matching diffuse term (same paper, eq. 5), energy-coupled to the specular layer:
//     f_diff = 28 R_d / (23 pi) (1 - R_s) (1 - (1 - n.l/2)^5) (1 - (1 - n.v/2)^5)
vec3 ashikhmin_shirley_diffuse(vec3 r_d, float r_s, float n_dot_l, float n_dot_v) {
    float a = 1.0 - pow(1.0 - 0.5 * max(n_dot_l, 0.0), 5.0);
    float c = 1.0 - pow(1.0 - 0.5 * max(n_dot_v, 0.0), 5.0);
    return 28.0 * r_d / (23.0 * kPi) * (1.0 - r_s) * a * c;
}

#endif
