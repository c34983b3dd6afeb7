// Noises built from passes/common/noise.glsl for the procedural presets (nothing here changes
// the functions there). The notes' GLSL built-ins noise1..noise4 (004_9a40ad89bdfc582a.txt
// L433-443) do not exist in Vulkan GLSL, so these stand in for them with an explicit hash.
#ifndef PASSLAB_PROCEDURAL_NOISE_EXT_GLSL
#define PASSLAB_PROCEDURAL_NOISE_EXT_GLSL
#include "common/noise.glsl"

// An arbitrary offset that moves the second component to an unrelated part of the lattice, so
// the two components are uncorrelated (any non-integer offset of a few cells works).
const vec3 kNoise2Offset = vec3(37.31, 17.77, 59.13);

// noise2(p) of L435/L476: two uncorrelated gradient noises, each in about [-1, 1] and 0 at
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

// Perlin's turbulence (Perlin 1985, the marble vase of L585-598): sum_{i<N} |n(2^i x)| / 2^i,
// the absolute value folding each octave into sharp creases; in [0, 2).
float turbulence(vec3 x, int octaves) {
    float sum = 0.0, amplitude = 1.0;
    for (int i = 0; i < octaves; ++i) {
        sum += amplitude * abs(gradient_noise(x));
        x *= 2.0;
        amplitude *= 0.5;
    }
    return sum;
}
#endif
