// Value noise, 004_9a40ad89bdfc582a.txt L262-313: random values at the integer lattice,
// interpolated with the fade h(t) = 3t^2 - 2t^3 (002_644d46bdce7e5305.txt L2385) or linearly.
// The result is remapped from [0,1] to [-1,1] so its mean is 0.
#include "common/hash.glsl"

float lattice_value(vec3 cell) {
    if (params.hash == HASH_SIN) {
        // The notes' hash: n = dot(floor(p), (1, 57, 113)) then fract(sin(n) * 43758.5453).
        float n = dot(cell, vec3(1.0, 57.0, 113.0));
        return fract(sin(n) * 43758.5453123);
    }
    return hash_pcg(cell);
}

float value_noise_lab(vec3 p) {
    vec3 i = floor(p);
    vec3 f = fract(p);
    vec3 w = params.fade == FADE_CUBIC ? f * f * (3.0 - 2.0 * f) : f;
    float n000 = lattice_value(i), n100 = lattice_value(i + vec3(1, 0, 0));
    float n010 = lattice_value(i + vec3(0, 1, 0)), n110 = lattice_value(i + vec3(1, 1, 0));
    float n001 = lattice_value(i + vec3(0, 0, 1)), n101 = lattice_value(i + vec3(1, 0, 1));
    float n011 = lattice_value(i + vec3(0, 1, 1)), n111 = lattice_value(i + vec3(1, 1, 1));
    float v = mix(mix(mix(n000, n100, w.x), mix(n010, n110, w.x), w.y),
                  mix(mix(n001, n101, w.x), mix(n011, n111, w.x), w.y), w.z);
    return 2.0 * v - 1.0;
}
