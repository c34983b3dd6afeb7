#version 450
// The compression ratio as stored (000 L1637: "Compression ratio 4:1 or 6:1"), two texels:
//   (0, 0): x bytes of the block buffer the copy pass reads (its runtime length: the whole
//           allocation), y texels of the bc1 image it fills (textureSize), z bits per texel
//   (1, 0): the ratio to uncompressed texels of x 4 bytes (RGBA8), y 3 bytes (RGB8),
//           z 2 bytes (RGB565)
// The copy refuses a buffer smaller than the image needs, so bytes >= texels / 2; equality here
// says the buffer holds nothing but kBc1BlockBytes for every 16 texels: 4 bits per texel, and
// the document's 6:1 is BC1 against RGB8; its 4:1 (L1637 does not say against what) holds for
// BC1 only against 16-bit (RGB565) texels, our reading. Against RGBA8, BC1 is 8:1 (the 4:1 for
// 32-bit texels belongs to the 16-byte BC2/BC3 blocks).
#include "texturing/bc1.glsl"
layout(location = 0) out vec4 info;
uniform sampler2D bc1;
layout(std430) readonly buffer Blocks { uvec2 words[]; } blocks;

const vec3 kUncompressedBytes = vec3(4.0, 3.0, 2.0);   // RGBA8, RGB8, RGB565 per texel

void main() {
    ivec2 size = textureSize(bc1, 0);
    float bytes = float(blocks.words.length()) * float(kBc1BlockBytes);
    float texels = float(size.x * size.y);
    if (int(gl_FragCoord.x) == 0) info = vec4(bytes, texels, 8.0 * bytes / texels, 0.0);
    else info = vec4(kUncompressedBytes * texels / bytes, 0.0);
}
