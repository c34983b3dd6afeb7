#version 450
// Pixel L = the mean of mip level L, summed texel by texel with texelFetch (no filtering).
// The level's size is derived from the base size: lavapipe (Mesa 22.3) returns wrong
// textureSize(s, lod) when lod differs between the pixels of a quad.
layout(location = 0) out float mean_out;
uniform sampler2D checker;
void main() {
    int level = int(gl_FragCoord.x);
    ivec2 size = max(textureSize(checker, 0) >> level, ivec2(1));
    float sum = 0.0;
    for (int y = 0; y < size.y; ++y)
        for (int x = 0; x < size.x; ++x) sum += texelFetch(checker, ivec2(x, y), level).r;
    mean_out = sum / float(size.x * size.y);
}
