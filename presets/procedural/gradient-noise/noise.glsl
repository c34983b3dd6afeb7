// 2D gradient noise, 004_9a40ad89bdfc582a.txt L344-389: random gradients g_ij at the integer
// corners of the cell containing P = (x, y) in [0,1]^2, the ramps
//     z00 = g00 . (x, y),  z10 = g10 . (x-1, y),  z01 = g01 . (x, y-1),  z11 = g11 . (x-1, y-1)
// blended bilinearly with a fade: h(t) = 3t^2 - 2t^3 (C1) or q(t) = 6t^5 - 15t^4 + 10t^3 (C2,
// because q''(0) = q''(1) = 0).
#include "common/hash.glsl"

vec2 lattice_gradient(vec2 cell) {
    // A random direction; unit length so |n| stays within sqrt(2)/2 before scaling.
    float a = 6.28318530718 * hash_pcg(vec3(cell, 7.0));
    return vec2(cos(a), sin(a));
}

float fade_curve(float t) {
    return params.fade == FADE_QUINTIC ? t * t * t * (t * (t * 6.0 - 15.0) + 10.0) : t * t * (3.0 - 2.0 * t);
}

float gradient_noise_2d(vec2 p) {
    vec2 i = floor(p), f = p - i;
    float z00 = dot(lattice_gradient(i), f);
    float z10 = dot(lattice_gradient(i + vec2(1, 0)), f - vec2(1, 0));
    float z01 = dot(lattice_gradient(i + vec2(0, 1)), f - vec2(0, 1));
    float z11 = dot(lattice_gradient(i + vec2(1, 1)), f - vec2(1, 1));
    vec2 u = vec2(fade_curve(f.x), fade_curve(f.y));
    // With unit gradients |n| <= sqrt(2)/2 (reached at a cell centre); scale to [-1, 1].
    return 1.41421356 * mix(mix(z00, z10, u.x), mix(z01, z11, u.x), u.y);
}
