#version 450
// Linear radiance to the display: Reinhard per channel, then the sRGB target encodes.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D hdr;
#include "post/tonemap.glsl"
void main() { color = vec4(tonemap_reinhard(params.exposure * texture(hdr, uv).rgb), 1.0); }
