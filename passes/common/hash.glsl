// Hash functions: map integer lattice points to pseudo-random values.
//
// hash_sin is the classic `fract(sin(dot(p, k)) * 43758.5453)` from the course notes
// (002_644d46bdce7e5305.txt L2379-2390). It is short but its result depends on the precision of
// sin() on large arguments, which differs between GPUs: fine for looks, risky for goldens.
// hash_pcg uses integer arithmetic only (PCG3D, Jarzynski & Olano 2020, "Hash Functions for GPU
// Rendering"), so every driver produces the same bits.
#ifndef PASSLAB_HASH_GLSL
#define PASSLAB_HASH_GLSL

float hash_sin(vec3 p) {
    return fract(sin(dot(p, vec3(12.9898, 78.233, 151.7182))) * 43758.5453123);
}

uvec3 pcg3d(uvec3 v) {
    v = v * 1664525u + 1013904223u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    v ^= v >> 16u;
    v.x += v.y * v.z;
    v.y += v.z * v.x;
    v.z += v.x * v.y;
    return v;
}

// Uniform in [0, 1) for an integer lattice point (given as float, e.g. floor(p)).
float hash_pcg(vec3 cell) {
    return float(pcg3d(uvec3(ivec3(cell))).x) * (1.0 / 4294967296.0);
}

vec3 hash_pcg3(vec3 cell) {
    return vec3(pcg3d(uvec3(ivec3(cell)))) * (1.0 / 4294967296.0);
}

#endif
