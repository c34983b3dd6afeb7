#version 450
// Exposure + Hejl (display-encoded, to a UNORM target).
#include "post/tonemap.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D hdr;
void main() { ldr = vec4(clamp(tonemap_hejl(texture(hdr, uv).rgb * params.exposure), 0.0, 1.0), 1.0); }
