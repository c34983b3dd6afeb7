// Lattice noises (004_9a40ad89bdfc582a.txt L262-389): random values or gradients at integer
// points, interpolated with a smooth fade.
//   value noise:    n(x) = lerp of random values r(i) at the cell corners, weights fade(f)
//   gradient noise: n(x) = lerp of dot(g(i), x - i) at the corners (zero at every lattice point)
// fade3(t) = 3t^2 - 2t^3 (C1, L2382 of 002); fade5(t) = 6t^5 - 15t^4 + 10t^3 (C2, Perlin 2002).
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

#endif
