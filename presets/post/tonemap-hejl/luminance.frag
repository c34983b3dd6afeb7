#version 450
// Luminance of the HDR image (or its log), resampled to 256x256 so its mip chain ends in one
// texel: the mean of what is stored. Averaging log(L) gives the geometric mean, which a few
// very bright pixels (the sun) cannot drag up the way they drag up the plain mean.
#include "post/tonemap.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out float lum;
uniform sampler2D hdr;
const float kEps = 1e-4;  // log(0) guard: black counts as 1e-4
void main() {
    float l = luminance(texture(hdr, uv).rgb);
    lum = params.mean == MEAN_LOG ? log(l + kEps) : l;
}
