#version 450
// Luminance, resampled to 256x256 so the mip chain ends in one texel: the mean (002 L660).
#include "common/color.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out float lum;
uniform sampler2D hdr;
void main() { lum = luminance(texture(hdr, uv).rgb); }
