// The fBm field of presets/procedural/fbm, shared by its fragment pass and by the compute
// variant of the benchmark (tests/bench/fbm-compute): one definition of the sum below.
//
//   perlin(x) = sum_{i=0}^{N-1} p^i * n(2^i x)        (004_9a40ad89bdfc582a.txt L315-342)
//
// with n = value noise in [0,1] and p the persistence. Like cloudFBM in
// 002_644d46bdce7e5305.txt L2395-2405 we divide by s = sum p^i, so f/s stays in n's range
// whatever N and p are, and optionally rotate the domain between octaves by the matrix printed
// there (times 2 + mm, mm growing 0.0059 per octave) so lattice lines of octaves do not align.
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
    float amp = 1.0;  // p^i
    float mm = 0.0;
    for (int i = 0; i < params.octaves; ++i) {
        f += amp * value_noise(p);
        s += amp;
        p = params.rotate ? kOctaveRotation * p * (2.0 + mm) : p * 2.0;
        // Offset each octave so the lattice origins do not coincide.
        p += vec3(17.13, 31.71, 5.37);
        amp *= params.persistence;
        mm += 0.0059;
    }
    return vec4(f / s, f, s, 1.0);
}
#endif
