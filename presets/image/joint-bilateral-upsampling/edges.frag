#version 450
// The edge band: r = 1 where a tap of p's 2x2 footprint belongs to another object (another ID)
// than p, the pixels where joint bilateral and bilinear upsampling differ by design; 0 in the
// flat regions.
#include "taps.glsl"

layout(location = 0) out vec4 color;
uniform sampler2D low_guide;
uniform sampler2D guide;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 tap[4]; float w[4];
    jbu_taps(p, frame.target.xy, textureSize(low_guide, 0), tap, w);
    float id = texelFetch(guide, p, 0).r;
    bool edge = false;
    for (int k = 0; k < 4; ++k) edge = edge || (w[k] > 0.0 && texelFetch(low_guide, tap[k], 0).r != id);
    color = vec4(edge ? 1.0 : 0.0, 0.0, 0.0, 1.0);
}
