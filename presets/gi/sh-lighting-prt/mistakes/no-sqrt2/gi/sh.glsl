// Real spherical harmonics: the basis, projection weights, evaluation and rotation about the
// polar axis, shared by the GI presets (gi/sh-lighting-prt: 4 bands, 16 coefficients;
// gi/radiance-hints: 2 bands, 4 coefficients).
//
// The basis is the one printed in 002_644d46bdce7e5305.txt L2504-2553, written out literally so
// that each factor can be checked against it:
//   s = (sin t cos p, sin t sin p, cos t)                                  (Equation 1)
//   K_l^m = sqrt((2l + 1) (l - |m|)! / (4 pi (l + |m|)!))                  (Equation 3)
//   y_l^m = sqrt(2) K_l^m cos( m p) P_l^m(cos t)     m > 0                 (Equation 4)
//           sqrt(2) K_l^m sin(|m| p) P_l^|m|(cos t)  m < 0
//           K_l^0 P_l^0(cos t)                       m = 0
// band l has 2l + 1 functions; coefficient (l, m) is stored at index l (l + 1) + m. The y_l^m
// are orthonormal over the sphere, so projection is f_lm = integral f y_l^m dw and the
// reconstruction sum f_lm y_l^m is the least-squares fit of f in the first bands.
//
// World space is y-up; the polar axis of the seed's Equation 1 is z. sh_frame() maps world
// (x, y, z) to the SH frame (x, -z, y) (right-handed), so the polar axis is world up: theta is
// the angle from +y, and a rotation of the environment about world +y (yaw) is a rotation about
// the polar axis, which mixes only (m, -m) pairs of a band (sh_rotate_polar).
#ifndef PASSLAB_GI_SH_GLSL
#define PASSLAB_GI_SH_GLSL

const float SH_PI = 3.14159265358979;

int sh_index(int l, int m) { return l * (l + 1) + m; }

vec3 sh_frame(vec3 w) { return vec3(w.x, -w.z, w.y); }

float sh_factorial(int n) {
    float f = 1.0;
    for (int i = 2; i <= n; ++i) f *= float(i);
    return f;
}

// Equation 3 (002 L2504-2553): the factor that makes each y_l^m have unit norm.
float sh_K(int l, int m) {
    int am = abs(m);
    return sqrt(float(2 * l + 1) * sh_factorial(l - am) / (4.0 * SH_PI * sh_factorial(l + am)));
}

// Associated Legendre polynomial P_l^m(x), m >= 0, by the standard recurrences (with the
// Condon-Shortley phase; the phase cancels between projection and reconstruction):
//   P_m^m = (-1)^m (2m - 1)!! (1 - x^2)^(m/2),  P_{m+1}^m = x (2m + 1) P_m^m,
//   (l - m) P_l^m = x (2l - 1) P_{l-1}^m - (l + m - 1) P_{l-2}^m.
float sh_legendre(int l, int m, float x) {
    float pmm = 1.0;
    if (m > 0) {
        float s = sqrt(max(0.0, (1.0 - x) * (1.0 + x))), f = 1.0;
        for (int i = 1; i <= m; ++i) { pmm *= -f * s; f += 2.0; }
    }
    if (l == m) return pmm;
    float pmm1 = x * float(2 * m + 1) * pmm;
    if (l == m + 1) return pmm1;
    float pll = 0.0;
    for (int ll = m + 2; ll <= l; ++ll) {
        pll = (x * float(2 * ll - 1) * pmm1 - float(ll + m - 1) * pmm) / float(ll - m);
        pmm = pmm1;
        pmm1 = pll;
    }
    return pll;
}

// Equation 4: the real basis function y_l^m from cos(theta) and the azimuth's cos(|m| phi),
// sin(|m| phi).
float sh_real_form(int l, int m, float cos_theta, float cos_m_phi, float sin_m_phi) {
    float k = sh_K(l, m) * sh_legendre(l, abs(m), cos_theta);
    if (m > 0) return k * cos_m_phi;
    if (m < 0) return k * sin_m_phi;
    return k;
}

// y_l^m at the world direction w (unit length).
float sh_basis(int l, int m, vec3 w) {
    vec3 s = sh_frame(w);
    float phi = atan(s.y, s.x);  // atan(0, 0) is 0 at the poles, where every m != 0 term is 0
    return sh_real_form(l, m, s.z, cos(float(abs(m)) * phi), sin(float(abs(m)) * phi));
}

// All bands^2 basis values at w (bands 2 or 4). The same functions as sh_basis, written out per
// (l, m) with literal arguments so that K_l^m and the Legendre recurrences fold to constants
// and polynomials (a loop over (l, m) indexing arrays costs ~3x more on llvmpipe), with the
// azimuth's harmonics computed once by angle addition (no atan, defined at the poles).
void sh_eval(vec3 w, int bands, out float y[16]) {
    vec3 s = sh_frame(w);
    float r = length(s.xy), z = s.z;
    vec2 e1 = r > 0.0 ? s.xy / r : vec2(1.0, 0.0);  // (cos phi, sin phi)
    vec2 e2 = vec2(e1.x * e1.x - e1.y * e1.y, 2.0 * e1.x * e1.y);
    vec2 e3 = vec2(e2.x * e1.x - e2.y * e1.y, e2.x * e1.y + e2.y * e1.x);
    for (int i = 0; i < 16; ++i) y[i] = 0.0;
    y[0] = sh_real_form(0, 0, z, 1.0, 0.0);
    y[1] = sh_real_form(1, -1, z, e1.x, e1.y);
    y[2] = sh_real_form(1, 0, z, 1.0, 0.0);
    y[3] = sh_real_form(1, 1, z, e1.x, e1.y);
    if (bands <= 2) return;
    y[4] = sh_real_form(2, -2, z, e2.x, e2.y);
    y[5] = sh_real_form(2, -1, z, e1.x, e1.y);
    y[6] = sh_real_form(2, 0, z, 1.0, 0.0);
    y[7] = sh_real_form(2, 1, z, e1.x, e1.y);
    y[8] = sh_real_form(2, 2, z, e2.x, e2.y);
    y[9] = sh_real_form(3, -3, z, e3.x, e3.y);
    y[10] = sh_real_form(3, -2, z, e2.x, e2.y);
    y[11] = sh_real_form(3, -1, z, e1.x, e1.y);
    y[12] = sh_real_form(3, 0, z, 1.0, 0.0);
    y[13] = sh_real_form(3, 1, z, e1.x, e1.y);
    y[14] = sh_real_form(3, 2, z, e2.x, e2.y);
    y[15] = sh_real_form(3, 3, z, e3.x, e3.y);
}

// Rotation of a band-limited function about the polar axis (world +y) by angle a:
// g(w) = f(R_y(-a) w). In the SH frame this is phi -> phi - a, and for each pair
// f = c cos(m phi) + s sin(m phi) of band l (the P_l^m factor is shared):
//   c' = c cos(m a) - s sin(m a),   s' = c sin(m a) + s cos(m a).
// m = 0 terms do not change (a yaw leaves the zonal part alone).
void sh_rotate_polar(inout vec3 c[16], int bands, float a) {
    for (int l = 1; l < bands; ++l)
        for (int m = 1; m <= l; ++m) {
            vec3 cp = c[sh_index(l, m)], sp = c[sh_index(l, -m)];
            float co = cos(float(m) * a), si = sin(float(m) * a);
            c[sh_index(l, m)] = cp * co - sp * si;
            c[sh_index(l, -m)] = cp * si + sp * co;
        }
}

// Node i (0..n-1) of the n-point Gauss-Legendre rule on [-1, 1] and its weight, by Newton's
// method on P_n from the Chebyshev-like first guess. The rule integrates polynomials of degree
// < 2n exactly, so a constant projects to band 0 only and 0.5 + 0.3 cos(theta) round-trips
// exactly (up to float rounding), which a midpoint rule in cos(theta) does not (its error on
// P_2 is ~h^2/4). Used with a uniform grid in phi (exact for cos(m phi), |m| < phi count).
void sh_gauss_legendre(int i, int n, out float x, out float weight) {
    x = cos(SH_PI * (float(i) + 0.75) / (float(n) + 0.5));
    float dp = 1.0;
    for (int it = 0; it < 8; ++it) {
        float p0 = 1.0, p1 = x;
        for (int k = 2; k <= n; ++k) {
            float p2 = (float(2 * k - 1) * x * p1 - float(k - 1) * p0) / float(k);
            p0 = p1;
            p1 = p2;
        }
        dp = float(n) * (x * p1 - p0) / (x * x - 1.0);  // P_n'(x)
        x -= p1 / dp;
    }
    weight = 2.0 / ((1.0 - x * x) * dp * dp);
}

// The world direction with cos(theta) = z (from +y) and azimuth phi in the SH frame.
vec3 sh_direction(float z, float phi) {
    float r = sqrt(max(0.0, 1.0 - z * z));
    vec3 s = vec3(r * cos(phi), r * sin(phi), z);
    return vec3(s.x, s.z, -s.y);  // the inverse of sh_frame
}

#endif
