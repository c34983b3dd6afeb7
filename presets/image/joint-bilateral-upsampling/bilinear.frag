#version 450
// Naive bilinear upsampling (000_c9f7e5de708ecbb3.txt L3246: "suppresses high frequencies"):
// the four nearest low-resolution colours, weighted by the bilinear weights.
#include "taps.glsl"

layout(location = 0) out vec4 color;
uniform sampler2D low_color;

void main() {
    ivec2 tap[4]; float w[4];
    jbu_taps(ivec2(gl_FragCoord.xy), frame.target.xy, textureSize(low_color, 0), tap, w);
    vec3 c = vec3(0.0);
    for (int k = 0; k < 4; ++k) c += w[k] * texelFetch(low_color, tap[k], 0).rgb;
    color = vec4(c, 1.0);
}
