#version 450
// Reference: the 5x5 Gaussian applied directly, 25 lookups with weights w(i) w(j) (the product
// kernel that makes the separable version exact). Texel-centre lookups, no filtering involved.
#include "post/gauss.glsl"

layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D src;

void main() {
    vec2 texel = 1.0 / vec2(textureSize(src, 0));
    vec4 c = vec4(0.0);
    for (int j = 0; j < 5; ++j)
        for (int i = 0; i < 5; ++i)
            c += kGauss5[i] * kGauss5[j] * texture(src, uv + vec2(i - 2, j - 2) * texel);
    color = c;
}
