// EXERCISE — this file shadows passes/procedural/noise_ext.glsl for procedural/marble-and-wood
// (solid.frag includes it). Only turbulence() is yours (TODO 1); the rest is the reference's.
//     passlab grade procedural/marble-and-wood --exercise presets/procedural/marble-and-wood/exercise
// Noises built from passes/common/noise.glsl for the procedural presets (nothing here changes
// the functions there). The notes' GLSL built-ins noise1..noise4 (004_9a40ad89bdfc582a.txt
// L433-443) do not exist in Vulkan GLSL, so these stand in for them with an explicit hash.
#ifndef PASSLAB_PROCEDURAL_NOISE_EXT_GLSL
#define PASSLAB_PROCEDURAL_NOISE_EXT_GLSL
#include "common/noise.glsl"

// An arbitrary offset that moves the second component to an unrelated part of the lattice, so
// the two components are uncorrelated (any non-integer offset of a few cells works).
const vec3 kNoise2Offset = vec3(37.31, 17.77, 59.13);

// noise2(p) of L434/L481: two uncorrelated gradient noises, each in about [-1, 1] and 0 at
// every integer point (gradient noise, L344-389).
vec2 gradient_noise2(vec3 p) {
    return vec2(gradient_noise(p), gradient_noise(p + kNoise2Offset));
}

// Fractal sum of L315-342, perlin(x) = sum_{i<N} p^i n(2^i x), with gradient noise for n
// (not normalised: with p = 1/2 its range is at most 2x that of n).
float perlin_sum(vec3 x, int octaves, float persistence) {
    float sum = 0.0, amplitude = 1.0;
    for (int i = 0; i < octaves; ++i) {
        sum += amplitude * gradient_noise(x);
        x *= 2.0;
        amplitude *= persistence;
    }
    return sum;
}

// TODO 1: Perlin's turbulence (Perlin 1985, "An image synthesizer"; the marble vase of
// 004 L585-598), the fractal sum of L315-342 built like perlin_sum above, but of the absolute
// value of each octave:
//     turbulence(x) = sum_{i<N} |n(2^i x)| / 2^i,   n = gradient_noise (signed, about [-1, 1]).
// Folding each octave at its zero crossings gives the sharp creases of the veins. Which range
// must the result have, and what would a signed sum do to the marble?
float turbulence(vec3 x, int octaves) {
    float sum = 0.0, amplitude = 1.0;
    for (int i = 0; i < octaves; ++i) {
        sum += amplitude * abs(gradient_noise(x));
        x *= 2.0;
        amplitude *= 0.5;
    }
    return sum;
}
// gradient_noise (passes/common/noise.glsl) with its analytic gradient: returns
// (n(p), grad n(p)). With f = fract(p), u = fade5(f) and the corner ramps z_c = g_c . (f - c):
//     n = trilinear mix of z_c with weights u
//     grad n = (trilinear mix of the g_c) + fade5'(f) * (dn/du.x, dn/du.y, dn/du.z)
// fade5'(t) = 30 t^2 (t - 1)^2. One evaluation instead of the six of central differences.
// The corner gradients are the same expression as gradient_noise's PL_GRAD.
vec3 gradient_noise_corner(vec3 cell) { return normalize(hash_pcg3(cell) * 2.0 - 1.0 + 1e-6); }
vec4 gradient_noise_d(vec3 p) {
    vec3 i = floor(p), f = fract(p);
    vec3 u = fade5(f), du = 30.0 * f * f * (f - 1.0) * (f - 1.0);
    vec3 g000 = gradient_noise_corner(i), g100 = gradient_noise_corner(i + vec3(1, 0, 0));
    vec3 g010 = gradient_noise_corner(i + vec3(0, 1, 0)), g110 = gradient_noise_corner(i + vec3(1, 1, 0));
    vec3 g001 = gradient_noise_corner(i + vec3(0, 0, 1)), g101 = gradient_noise_corner(i + vec3(1, 0, 1));
    vec3 g011 = gradient_noise_corner(i + vec3(0, 1, 1)), g111 = gradient_noise_corner(i + vec3(1, 1, 1));
    float z000 = dot(g000, f), z100 = dot(g100, f - vec3(1, 0, 0));
    float z010 = dot(g010, f - vec3(0, 1, 0)), z110 = dot(g110, f - vec3(1, 1, 0));
    float z001 = dot(g001, f - vec3(0, 0, 1)), z101 = dot(g101, f - vec3(1, 0, 1));
    float z011 = dot(g011, f - vec3(0, 1, 1)), z111 = dot(g111, f - vec3(1, 1, 1));
    float n = mix(mix(mix(z000, z100, u.x), mix(z010, z110, u.x), u.y),
                  mix(mix(z001, z101, u.x), mix(z011, z111, u.x), u.y), u.z);
    vec3 ramps = mix(mix(mix(g000, g100, u.x), mix(g010, g110, u.x), u.y),
                     mix(mix(g001, g101, u.x), mix(g011, g111, u.x), u.y), u.z);
    vec3 dn_du = vec3(
        mix(mix(z100 - z000, z110 - z010, u.y), mix(z101 - z001, z111 - z011, u.y), u.z),
        mix(mix(z010 - z000, z110 - z100, u.x), mix(z011 - z001, z111 - z101, u.x), u.z),
        mix(mix(z001 - z000, z101 - z100, u.x), mix(z011 - z010, z111 - z110, u.x), u.y));
    return vec4(n, ramps + du * dn_du);
}

// perlin_sum with its gradient: (sum, grad sum); octave i contributes p^i 2^i grad n(2^i x).
vec4 perlin_sum_d(vec3 x, int octaves, float persistence) {
    vec4 sum = vec4(0.0);
    float amplitude = 1.0, scale = 1.0;
    for (int i = 0; i < octaves; ++i) {
        vec4 nd = gradient_noise_d(x * scale);
        sum += amplitude * vec4(nd.x, scale * nd.yzw);
        scale *= 2.0;
        amplitude *= persistence;
    }
    return sum;
}
#endif
