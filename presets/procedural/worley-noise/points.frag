#version 450
// F1 at the feature point of cell (x + 100, y + 100): must be 0.
#include "common/noise.glsl"
layout(location = 0) out float points;
void main() { points = worley_noise(worley_point(floor(gl_FragCoord.xy) + 100.0)).x; }
