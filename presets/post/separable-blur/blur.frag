#version 450
// One direction of the separable 5-tap Gaussian (000_c9f7e5de708ecbb3.txt L3020-3077).
// Note the listing's pitfall: its `#ifndef BLUR_Y` selects dir = (0,1), i.e. it blurs along y
// when BLUR_Y is NOT defined. Here BLUR_X means "along x" and nothing else.
#include "post/gauss.glsl"

layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D blur_in;

#ifdef BLUR_X
const vec2 kDir = vec2(1.0, 0.0);
#else
const vec2 kDir = vec2(0.0, 1.0);
#endif

void main() {
    vec2 texel = kDir / vec2(textureSize(blur_in, 0));
    color = params.kernel == KERNEL_LINEAR ? gauss5_linear(blur_in, uv, texel)
                                           : gauss5_discrete(blur_in, uv, texel);
}
