// EXERCISE — 2D simplex noise (004_9a40ad89bdfc582a.txt L391-443). This file shadows
// passes/common/noise.glsl for procedural/simplex-noise: noise.frag (the image), corners.frag
// (the zero-at-the-corners check) and display.frag include it. Value, gradient and Worley noise
// below are the library's, unchanged; fill in the four TODO blocks of the simplex section.
//     passlab run   procedural/simplex-noise --exercise presets/procedural/simplex-noise/exercise
//     passlab grade procedural/simplex-noise --exercise presets/procedural/simplex-noise/exercise
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
// the plane tiled by equilateral triangles, which a skew turns into the square grid with each
// square cut along a diagonal (the cube "compressed along one of its diagonals", 004 L412-416).
// Only the 3 corners of the point's triangle contribute (004 L421-425), so the cost is d + 1
// corners in d dimensions instead of the 2^d of lattice noise.
//
// TODO 1: the skew and unskew factors. In n dimensions the skew s = x + (x_1 + ... + x_n) F_n
// maps the simplex lattice to the integer grid, and the unskew x = s - (s_1 + ... + s_n) G_n
// maps it back, with
//     F_n = (sqrt(n + 1) - 1) / n,        G_n = (1 - 1 / sqrt(n + 1)) / n.
// Set both for n = 2 (for n = 3 they are 1/3 and 1/6: the 3D listings' constants, not these).
const float kSimplexF2 = 0.36602540378;  // (sqrt(3) - 1) / 2
const float kSimplexG2 = 0.21132486540;  // (3 - sqrt(3)) / 6

// TODO 2a: unskew a corner given in skewed integer coordinates to the plane (the G_n map of
// TODO 1). corners.frag evaluates the noise at simplex_corner(cell) and expects exactly 0 there.
vec2 simplex_corner(vec2 skewed_cell) { return skewed_cell - (skewed_cell.x + skewed_cell.y) * kSimplexG2; }

float simplex_noise(vec2 p) {
    // TODO 2b: "determine the simplex in which a query point P lies" (004 L421): skew p (the
    // F_n map of TODO 1) and take floor to get its skewed cell i; x0 is p's offset from that
    // cell's first corner, unskewed into the plane (simplex_corner).
    vec2 i = floor(p + (p.x + p.y) * kSimplexF2);
    vec2 x0 = p - simplex_corner(i);
    // TODO 3: "determine all of its vertices" (004 L422). The skewed square i is cut along its
    // diagonal into a lower triangle (corners i, i + (1, 0), i + (1, 1)) and an upper one
    // (i, i + (0, 1), i + (1, 1)); the order of x0's two coordinates says which holds p. o is
    // the middle corner's step from i; x1 and x2 are p's offsets from corners i + o and i + 1,
    // in the plane: each unskewed step of k skewed units in total moves by -k G2 in x and y.
    vec2 o = x0.x > x0.y ? vec2(0.0, 1.0) : vec2(1.0, 0.0);  // (mistake: the other triangle's middle corner)
    vec2 x1 = x0 - o + kSimplexG2, x2 = x0 - 1.0 + 2.0 * kSimplexG2;
    float n = 0.0;
    vec2 corners[3] = vec2[](i, i + o, i + 1.0);
    vec2 offsets[3] = vec2[](x0, x1, x2);
    for (int k = 0; k < 3; ++k) {
        float a = 6.2831853 * hash_pcg(vec3(corners[k], 7.0));
        vec2 g = vec2(cos(a), sin(a));  // the corner's random unit gradient
        // TODO 4: the corner's "gradient ramp" dot(g, offset) (004 L423), weighted by the radial
        // kernel max(0, 0.5 - r^2)^4 with r = |offset| (004 L424-425: r^2 = 0.5 is where a
        // corner's influence ends, at the edges of its incident triangles), added to n.
        float t = max(0.5 - dot(offsets[k], offsets[k]), 0.0);
        n += t * t * t * t * dot(g, offsets[k]);
    }
    return 70.0 * n;  // scales the sum to about [-1, 1]
}

// Worley (cellular) noise (004_9a40ad89bdfc582a.txt L508-579): one feature point per unit cell,
// jittered by a hash of the cell; F_k = distance to the k-th nearest. Returns (F1, F2, F3). The
// listing searches 3x3 cells (enough for F1, which is at most sqrt 2: the own cell's point is
// never farther than the cell's diagonal); F2 and F3 can lie further out, so we search 5x5
// (docs/catalogue.md pitfall). The listing's `frac` is HLSL; GLSL's is fract.
vec2 worley_point(vec2 cell) { return cell + hash_pcg3(vec3(cell, 3.0)).xy; }
vec3 worley_noise(vec2 p) {
    vec2 c = floor(p);
    vec3 f = vec3(1e9);  // F1 <= F2 <= F3, kept sorted
    for (int y = -2; y <= 2; ++y)
        for (int x = -2; x <= 2; ++x) {
            float d = length(worley_point(c + vec2(x, y)) - p);
            if (d < f.x) f = vec3(d, f.x, f.y);
            else if (d < f.y) f = vec3(f.x, d, f.y);
            else if (d < f.z) f.z = d;
        }
    return f;
}

#endif
