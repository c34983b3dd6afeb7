// EXERCISE — fractal Brownian motion (004_9a40ad89bdfc582a.txt L315-342): octaves of value
// noise, each at twice the frequency and p times the amplitude of the one before, normalised by
// the sum of the amplitudes as cloudFBM does (002_644d46bdce7e5305.txt L2395-2405).
// This file shadows the preset's fbm.glsl, which fbm.frag includes.
//     passlab run   procedural/fbm --exercise presets/procedural/fbm/exercise
//     passlab grade procedural/fbm --exercise presets/procedural/fbm/exercise
// value_noise(p) (passes/common/noise.glsl) is done for you: value noise in [0, 1].
// Fill in the four TODO blocks of fbm_field; keep its loop, the rotation and the offsets.
#ifndef PRESET_FBM_GLSL
#define PRESET_FBM_GLSL
#include "common/noise.glsl"

// The octave rotation of 002 L2400 (a rotation scaled by 1: rows are orthonormal).
const mat3 kOctaveRotation = mat3(0.00, 0.80, 0.60, -0.80, 0.36, -0.48, -0.60, -0.48, 0.64);

// uv in [0,1]^2 (top-left origin). Returns (f/s, f, s, 1).
vec4 fbm_field(vec2 uv) {
    vec3 p = vec3((uv - 0.5) * vec2(frame.aspect, 1.0) * params.scale, frame.time * params.speed);
    float f = 0.0;    // sum of p^i n_i
    float s = 0.0;    // sum of p^i
    float amp = 1.0;  // p^i, the amplitude of octave i
    float mm = 0.0;
    for (int i = 0; i < params.octaves; ++i) {
        // TODO 1: add octave i to the two sums (004 L325, 002 L2398-2399): f gets this octave's
        // noise value n_i at p, weighted by its amplitude; s gets the amplitude alone.
        f += amp * value_noise(p);
        s += amp;

        // TODO 2: the next octave samples the noise at twice the frequency (the 2^i x of
        // 004 L325). With params.rotate, 002 L2400 also rotates the domain: p becomes
        // kOctaveRotation * p, scaled by (2 + mm) instead of exactly 2.
        p = params.rotate ? kOctaveRotation * p * (2.0 + mm) : p * 2.0;

        // Offset each octave so the lattice origins do not coincide.
        p += vec3(17.13, 31.71, 5.37);
        // TODO 3: the next octave's amplitude, p^(i+1): the persistence params.persistence is
        // "successive scaling of amplitude on successive octaves" (004 L323, 002 L2401).
        // (mistake: amp is never scaled, every octave is as loud as the first)

        mm += 0.0059;
    }
    // TODO 4: normalise (002 L2404) so the result stays in the noise's range [0, 1] whatever
    // the number of octaves and the persistence are. Return (normalised, f, s, 1).
    return vec4(f / s, f, s, 1.0);
}
#endif
