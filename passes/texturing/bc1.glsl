// BC1 (S3TC / DXT1) block codec: the decoder of the format, and the helpers an encoder needs.
// 000_c9f7e5de708ecbb3.txt L1629-1641: "Represent 4x4 texel block by two 16bit colors (RGB
// 5/6/5bit), store 2 bits per texel; uncompress: create 2 additional colors between c_1 and c_2,
// use 2 bits to index into color map; compression ratio 4:1 or 6:1".
//
// One block = 64 bits = two 32-bit words, laid out as a copy into a bc1_rgba image expects
// (little-endian bytes, blocks row by row):
//   word 0: color0 in bits 0..15, color1 in bits 16..31, each RGB565 (R bits 15..11, G 10..5,
//           B 4..0 of its 16 bits)
//   word 1: sixteen 2-bit palette indices; texel (x, y) of the block at bits 2 (4 y + x)
// Colours here are in 8-bit units (0..255), as the 5:6:5 endpoints expand to 8 bits.
#ifndef PASSLAB_TEXTURING_BC1_GLSL
#define PASSLAB_TEXTURING_BC1_GLSL

const int kBc1BlockSide = 4;      // a block covers 4 x 4 texels
const uint kBc1BlockBytes = 8u;   // 2 x 16-bit colours + 16 x 2-bit indices = 64 bits

// RGB565 -> 8 bits per channel by bit replication, (q << 3) | (q >> 2) for 5 bits: 0 -> 0 and
// 31 -> 255 exactly. (The exact UNORM value q * 255 / 31 differs from it by at most 0.68 of an
// 8-bit step, at q = 3 and 28.)
vec3 bc1_expand565(uint c) {
    uvec3 q = uvec3((c >> 11) & 31u, (c >> 5) & 63u, c & 31u);
    return vec3(uvec3((q.x << 3) | (q.x >> 2), (q.y << 2) | (q.y >> 4), (q.z << 3) | (q.z >> 2)));
}

// The RGB565 code nearest to an 8-bit colour (0..255 per channel): round(c (2^n - 1) / 255).
// Checked over all 256 values of each channel: its expansion is always a nearest one (ties at
// 12 red and 30 green values may go either way). Truncation (c >> 3, c >> 2), the common shortcut,
// is off by up to 7 steps in 5 bits instead of 4.
uint bc1_quantize565(vec3 c) {
    uvec3 q = uvec3(floor(clamp(c, 0.0, 255.0) * vec3(31.0, 63.0, 31.0) / 255.0 + 0.5));
    return (q.x << 11) | (q.y << 5) | q.z;
}

// The colour map of a block (000 L1634-1636), 8-bit units in rgb, alpha 0 or 1. The mode is
// given by comparing the two 16-bit colours as unsigned integers:
//   color0 >  color1: four colours, c2 = (2 c0 + c1) / 3, c3 = (c0 + 2 c1) / 3
//   color0 <= color1: three colours, c2 = (c0 + c1) / 2, and index 3 = transparent black
// The interpolants are the exact fractions of the format's definition; hardware rounds them to
// its 8-bit (or finer) precision in its own way, which the preset measures.
void bc1_palette(uint color0, uint color1, out vec4 pal[4]) {
    vec3 a = bc1_expand565(color0);
    vec3 b = bc1_expand565(color1);
    pal[0] = vec4(a, 1.0);
    pal[1] = vec4(b, 1.0);
    if (color0 > color1) {
        pal[2] = vec4((2.0 * a + b) / 3.0, 1.0);
        pal[3] = vec4((a + 2.0 * b) / 3.0, 1.0);
    } else {
        pal[2] = vec4((a + b) / 2.0, 1.0);
        pal[3] = vec4(0.0);
    }
}

// Which block of a buffer holds texel t of an image width_texels wide (blocks row by row), and
// where in the block the texel is.
int bc1_block_of(ivec2 t, int width_texels) { return (t.y / kBc1BlockSide) * (width_texels / kBc1BlockSide) + t.x / kBc1BlockSide; }
ivec2 bc1_in_block(ivec2 t) { return t % kBc1BlockSide; }

// Index of texel t (0..3, 0..3) of the block.
uint bc1_index(uvec2 block, ivec2 t) { return (block.y >> (2u * uint(t.y * kBc1BlockSide + t.x))) & 3u; }

// True when the block is in three-colour + transparent mode.
bool bc1_three_colour(uvec2 block) { return (block.x & 0xFFFFu) <= (block.x >> 16); }

// Decode texel t of a block to a colour in 0..1 (what a sampler of a bc1_rgba image returns).
vec4 bc1_decode(uvec2 block, ivec2 t) {
    vec4 pal[4];
    bc1_palette(block.x & 0xFFFFu, block.x >> 16, pal);
    vec4 c = pal[bc1_index(block, t)];
    return vec4(c.rgb / 255.0, c.a);
}

#endif
