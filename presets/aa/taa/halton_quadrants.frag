#version 450
// How many of the 8 jitter points fall in this texel's quadrant of the pixel (2x2 image).
#include "aa/taa_jitter.glsl"
layout(location = 0) out float quadrants;
void main() {
    ivec2 q = ivec2(gl_FragCoord.xy);
    int n = 0;
    for (int i = 1; i <= 8; ++i) n += ivec2(halton23(i) * 2.0) == q ? 1 : 0;
    quadrants = float(n);
}
