#version 450
// Additive particles sum to values well above 1 where they overlap: Hejl's filmic curve
// (post/tonemap.glsl, 002_644d46bdce7e5305.txt L641-646) rolls them off instead of clipping,
// into a UNORM target (the curve includes the display gamma).
#include "post/tonemap.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 ldr;
uniform sampler2D hdr;
void main() { ldr = vec4(tonemap_hejl(texture(hdr, uv).rgb), 1.0); }
