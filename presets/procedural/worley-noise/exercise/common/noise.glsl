// EXERCISE — Worley (cellular) noise (004_9a40ad89bdfc582a.txt L508-579). This file shadows
// passes/common/noise.glsl for procedural/worley-noise: worley.frag (the image), points.frag
// (the zero-at-feature-points check) and brute.frag (the search check) include it. Value,
// gradient and simplex noise above the Worley section are the library's, unchanged; fill in
// the two TODO blocks of worley_noise.
//     passlab run   procedural/worley-noise --exercise presets/procedural/worley-noise/exercise
//     passlab grade procedural/worley-noise --exercise presets/procedural/worley-noise/exercise
//
// Lattice noises (004_9a40ad89bdfc582a.txt L262-389): random values or gradients at integer
// points, interpolated with a smooth fade.
//   value noise:    n(x) = lerp of random values r(i) at the cell corners, weights fade(f)
//   gradient noise: n(x) = lerp of dot(g(i), x - i) at the corners (zero at every lattice point)
// fade3(t) = 3t^2 - 2t^3 (C1, L2385 of 002); fade5(t) = 6t^5 - 15t^4 + 10t^3 (C2, Perlin 2002).
#ifndef PASSLAB_NOISE_GLSL
#define PASSLAB_NOISE_GLSL

#include "common/hash.glsl"

vec3 fade3(vec3 t) { return t * t * (3.0 - 2.0 * t); }
vec3 fade5(vec3 t) { return t * t * t * (t * (t * 6.0 - 15.0) + 10.0); }

// Value noise in [0, 1]; exact hash values at integer points.
float value_noise(vec3 p) {
    vec3 i = floor(p);
    vec3 f = fade3(fract(p));
    float n000 = hash_pcg(i + vec3(0, 0, 0)), n100 = hash_pcg(i + vec3(1, 0, 0));
    float n010 = hash_pcg(i + vec3(0, 1, 0)), n110 = hash_pcg(i + vec3(1, 1, 0));
    float n001 = hash_pcg(i + vec3(0, 0, 1)), n101 = hash_pcg(i + vec3(1, 0, 1));
    float n011 = hash_pcg(i + vec3(0, 1, 1)), n111 = hash_pcg(i + vec3(1, 1, 1));
    return mix(mix(mix(n000, n100, f.x), mix(n010, n110, f.x), f.y),
               mix(mix(n001, n101, f.x), mix(n011, n111, f.x), f.y), f.z);
}

// Gradient noise in about [-1, 1]; exactly 0 at integer points.
float gradient_noise(vec3 p) {
    vec3 i = floor(p);
    vec3 f = fract(p);
    vec3 u = fade5(f);
    // Random unit-ish gradient per corner.
#define PL_GRAD(o) dot(normalize(hash_pcg3(i + o) * 2.0 - 1.0 + 1e-6), f - o)
    float n000 = PL_GRAD(vec3(0, 0, 0)), n100 = PL_GRAD(vec3(1, 0, 0));
    float n010 = PL_GRAD(vec3(0, 1, 0)), n110 = PL_GRAD(vec3(1, 1, 0));
    float n001 = PL_GRAD(vec3(0, 0, 1)), n101 = PL_GRAD(vec3(1, 0, 1));
    float n011 = PL_GRAD(vec3(0, 1, 1)), n111 = PL_GRAD(vec3(1, 1, 1));
#undef PL_GRAD
    return mix(mix(mix(n000, n100, u.x), mix(n010, n110, u.x), u.y),
               mix(mix(n001, n101, u.x), mix(n011, n111, u.x), u.y), u.z);
}

// 2D simplex noise (004_9a40ad89bdfc582a.txt L391-443; Gustavson, "Simplex noise demystified"):
// the plane tiled by triangles (the square grid skewed by F2 = (sqrt 3 - 1)/2), the point's
// triangle found from the skewed cell and the order of its coordinates, and only its 3 corners
// contribute, each with a radial kernel (0.5 - r^2)^4 times dot(gradient, offset). O(d + 1)
// corners instead of 2^d. Range about [-1, 1] (scale 70); exactly 0 at every corner: a corner's
// own term is dot(g, 0) and its neighbours are 2/3 away in r^2, beyond the kernel's 0.5.
const float kSimplexF2 = 0.36602540378;  // (sqrt(3) - 1) / 2
const float kSimplexG2 = 0.21132486540;  // (3 - sqrt(3)) / 6
vec2 simplex_corner(vec2 skewed_cell) { return skewed_cell - (skewed_cell.x + skewed_cell.y) * kSimplexG2; }
float simplex_noise(vec2 p) {
    vec2 i = floor(p + (p.x + p.y) * kSimplexF2);       // skewed cell
    vec2 x0 = p - simplex_corner(i);                      // offset from its first corner
    vec2 o = x0.x > x0.y ? vec2(1.0, 0.0) : vec2(0.0, 1.0);  // lower or upper triangle
    vec2 x1 = x0 - o + kSimplexG2, x2 = x0 - 1.0 + 2.0 * kSimplexG2;
    float n = 0.0;
    vec2 corners[3] = vec2[](i, i + o, i + 1.0);
    vec2 offsets[3] = vec2[](x0, x1, x2);
    for (int k = 0; k < 3; ++k) {
        float t = 0.5 - dot(offsets[k], offsets[k]);
        if (t > 0.0) {
            float a = 6.2831853 * hash_pcg(vec3(corners[k], 7.0));
            n += t * t * t * t * dot(vec2(cos(a), sin(a)), offsets[k]);
        }
    }
    return 70.0 * n;
}

// Worley (cellular) noise (004_9a40ad89bdfc582a.txt L508-579): one feature point per unit cell,
// jittered by a hash of the cell (004 L548-553); F_k(x) = distance of x to the k-th closest
// feature point (L511-512), F1 <= F2 <= F3 (L519). Returns (F1, F2, F3).
// worley_point is done for you: the feature point of a cell, in the plane's coordinates.
vec2 worley_point(vec2 cell) { return cell + hash_pcg3(vec3(cell, 3.0)).xy; }
vec3 worley_noise(vec2 p) {
    vec2 c = floor(p);   // "convert x to cell coords (i, j)" (004 L554)
    vec3 f = vec3(1e9);  // F1 <= F2 <= F3, kept sorted; 1e9 = nothing found yet
    // TODO 1: the search window, cells c + (x, y) with |x|, |y| <= kReach. 004 L555 searches
    // "from cell (i, j) outwards until the k-th closest P_i is found"; the listing of L569-577
    // stops at the 3 x 3 cells around c, which is written for F1 only. This function returns
    // F3 too: how far out can the third-nearest point be, and so how many rings of cells
    // around c must be searched before no point outside can be nearer?
    const int kReach = 0;
    for (int y = -kReach; y <= kReach; ++y)
        for (int x = -kReach; x <= kReach; ++x) {
            float d = length(worley_point(c + vec2(x, y)) - p);
            // TODO 2: keep the three smallest distances seen so far, sorted (L519): the listing
            // keeps only the minimum (m_dist = min(m_dist, dist), L577); here d must go to its
            // place among F1, F2, F3, moving the larger ones up one place, whichever of the
            // three it is smaller than.
        }
    return f;
}

#endif
