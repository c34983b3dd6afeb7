#version 450
// Texel-exact readout, one fragment per texel of the texture: the hardware's BC1 decode
// (texelFetch of the bc1_rgba image the copy pass filled, and of its bc1_rgba_srgb twin filled
// from the same blocks) beside the shader's own decode of the same buffer (bc1_decode:
// RGB565 unpack, four- or three-colour mode by color0 > color1, 2-bit index per texel).
// texelFetch: no filtering or coordinate rounding can hide a decode difference.
#include "texturing/bc1.glsl"
#include "common/color.glsl"
layout(location = 0) out vec4 hw;        // hardware, bc1_rgba
layout(location = 1) out vec4 sw;        // shader, same blocks
layout(location = 2) out vec4 hw_srgb;   // hardware, bc1_rgba_srgb: decoded, then sRGB -> linear
layout(location = 3) out vec4 sw_srgb;   // shader decode, then srgb_to_linear (color.glsl)
uniform sampler2D bc1;
uniform sampler2D bc1_srgb;
layout(std430) readonly buffer Blocks { uvec2 words[]; } blocks;

void main() {
    ivec2 t = ivec2(gl_FragCoord.xy);
    uvec2 block = blocks.words[bc1_block_of(t, textureSize(bc1, 0).x)];
    hw = texelFetch(bc1, t, 0);
    sw = bc1_decode(block, bc1_in_block(t));
    hw_srgb = texelFetch(bc1_srgb, t, 0);
    sw_srgb = vec4(srgb_to_linear(sw.rgb), sw.a);
}
