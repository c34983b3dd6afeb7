// The generators under test, each as a sequence u_0, u_1, ... of 32-bit fractions
// (x_i = u_i / 2^32), and the point that the spectral test plots for index i
// (004_9a40ad89bdfc582a.txt L616-680: "calculate x_i = rand() ... create a 2D scatter plot of
// all points (x_i, x_{i+1}), or in 3D using (x_i, x_{i+1}, x_{i+2})").
//
//   randu: IBM's RANDU, x_{n+1} = 65539 x_n mod 2^31 (L672, the notes' bad example)
//   lcg:   Numerical Recipes' "quick and dirty" x_{n+1} = 1664525 x_n + 1013904223 mod 2^32
//   pcg:   a hash of the index, u_i = pcg3d(i, seed, 0).x (passes/common/hash.glsl)
//   sin:   the shader hash of 002_644d46bdce7e5305.txt L1152-1155 / L2379-2381,
//          x_i = fract(sin(i) * 43758.5453): its low bits depend on the driver's sin()
//          (docs/catalogue.md pitfall), so it is shown but kept out of the goldens.
#include "common/hash.glsl"

const uint kRanduA = 65539u;               // 2^16 + 3
const uint kRanduMask = 0x7fffffffu;       // mod 2^31
const uint kLcgA = 1664525u, kLcgC = 1013904223u;
const float kSinScale = 43758.5453;

// The affine map x -> a x + c (mod 2^32) applied n times, by squaring: returns (A, C) with
// f^n(x) = A x + C. f o f = a^2 x + c (a + 1); powers of f commute, so the order is free.
uvec2 affine_power(uint a, uint c, uint n) {
    uint acc_a = 1u, acc_c = 0u;
    while (n > 0u) {
        if ((n & 1u) != 0u) { acc_a *= a; acc_c = acc_c * a + c; }
        c *= a + 1u;
        a *= a;
        n >>= 1u;
    }
    return uvec2(acc_a, acc_c);
}

struct Sequence { uint state; uint index; };

// The sequence positioned at index i (jump-ahead, so every invocation can start anywhere).
Sequence sequence_at(uint i) {
    uint seed = uint(params.seed);
    Sequence s = Sequence(0u, i);
    if (params.generator == GENERATOR_RANDU) {
        // RANDU needs an odd seed; x_i = 65539^i x_0 mod 2^31 (mod 2^32 then mask: 2^31 | 2^32).
        s.state = (affine_power(kRanduA, 0u, i).x * (seed | 1u)) & kRanduMask;
    } else if (params.generator == GENERATOR_LCG) {
        uvec2 f = affine_power(kLcgA, kLcgC, i);
        s.state = f.x * seed + f.y;
    }
    return s;
}

// u_i as a 32-bit fraction, then advance to i + 1.
uint sequence_next(inout Sequence s) {
    uint u;
    if (params.generator == GENERATOR_RANDU) {
        u = s.state << 1u;                                  // 31-bit x / 2^31 = (2x) / 2^32
        s.state = (s.state * kRanduA) & kRanduMask;
    } else if (params.generator == GENERATOR_LCG) {
        u = s.state;
        s.state = s.state * kLcgA + kLcgC;
    } else if (params.generator == GENERATOR_PCG) {
        u = pcg3d(uvec3(s.index, uint(params.seed), 0u)).x;
    } else {
        float x = fract(sin(float(s.index) + float(params.seed)) * kSinScale);
        u = uint(x * 4294967296.0);  // x <= 0.99999994, so u < 2^32
    }
    s.index++;
    return u;
}

// The plotted point for the triple (u_i, u_{i+1}, u_{i+2}), as 32-bit fractions in [0, 1)^2:
//   pairs:  (x_i, x_{i+1}), L663
//   planes: (x_i, fract(9 x_i - 6 x_{i+1} + x_{i+2})): the triple measured along RANDU's dual
//           lattice vector (9, -6, 1). Since 65539^2 = 6 * 65539 - 9 (mod 2^31),
//           x_{i+2} = 6 x_{i+1} - 9 x_i (mod 1) for RANDU, so its triples lie on the 15 planes
//           9x - 6y + z = k of L672's picture and the second coordinate is exactly 0. For a
//           generator whose x_{i+2} is uniform and independent of (x_i, x_{i+1}) it is uniform.
//           Mod 2^32 arithmetic on the fractions gives the fract() exactly. We add 1/2
//           (kHalf) so that RANDU's 0 plots as a line through the middle (histogram row 16),
//           not along the border.
//   cube:   the unit cube of triples (L664: "or in 3D") seen edge-on to those planes: screen
//           y along (9, -6, 1), screen x along (-9, 6, 117) (perpendicular to it and to the view
//           direction (-6, -9, 0), which lies in the planes). RANDU shows its planes as lines
//           1/sqrt(118) apart; any generator fills a hexagon-like shadow of the cube, so this
//           histogram is not uniform even for a good one (it is for looking).
const uint kHalf = 0x80000000u;                           // 1/2 as a 32-bit fraction
const vec3 kCubeUp = vec3(9.0, -6.0, 1.0) / 10.8627805;    // / sqrt(118)
const vec3 kCubeRight = vec3(-9.0, 6.0, 117.0) / 117.4989; // / sqrt(13806)
const float kCubeScale = 0.65;  // |q.up| <= 16 / (2 sqrt 118) = 0.736 -> within 0.48 of 0.5
const float kTwo32 = 4294967296.0;
uvec2 plotted_point(uint u0, uint u1, uint u2) {
    if (params.plot == PLOT_PAIRS) return uvec2(u0, u1);
    if (params.plot == PLOT_PLANES) return uvec2(u0, 9u * u0 - 6u * u1 + u2 + kHalf);
    vec3 q = vec3(u0, u1, u2) / kTwo32 - 0.5;
    vec2 s = clamp(vec2(dot(q, kCubeRight), dot(q, kCubeUp)) * kCubeScale + 0.5, 0.0, 0.99999994);
    return uvec2(s * kTwo32);
}
