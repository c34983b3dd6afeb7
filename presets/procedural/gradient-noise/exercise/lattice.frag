#version 450
// Pixel (x, y) evaluates the noise exactly at lattice point (x - 8, y - 8).
#include "noise.glsl"
layout(location = 0) out float n;
void main() { n = gradient_noise_2d(floor(gl_FragCoord.xy) - 8.0); }
