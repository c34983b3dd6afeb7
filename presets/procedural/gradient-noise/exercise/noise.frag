#version 450
#include "noise.glsl"
layout(location = 0) out float n;
void main() { n = gradient_noise_2d(gl_FragCoord.xy / frame.resolution.y * params.cells); }
