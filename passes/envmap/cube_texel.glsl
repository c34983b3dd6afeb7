// Cube map texels as directions with solid angles, for convolutions and checks. A texel of a
// face of n x n texels centred at face coordinates (s, t) in [-1, 1] covers about
//     d(omega) = (2/n)^2 / (1 + s^2 + t^2)^(3/2)
// (the area on the plane at distance 1, projected onto the unit sphere); the six faces sum to
// 4 pi to well under 1e-3 for n >= 16.
#ifndef PASSLAB_CUBE_TEXEL_GLSL
#define PASSLAB_CUBE_TEXEL_GLSL
#include "envmap/cube.glsl"
float cube_texel_solid_angle(vec2 uv, int n) {
    vec2 st = uv * 2.0 - 1.0;
    float a = 2.0 / float(n);
    return a * a / pow(1.0 + dot(st, st), 1.5);
}
#endif
