#version 450
// Tone calibration, step 2 (bake = true): texel i of the table is the fraction of the tile
// covered by strokes 0 .. i, C(i) = sum of the histogram up to i / texels (i = kStrokes, the
// uncovered texels: 1). Inking a texel whose first stroke has C(index) <= darkness covers
// exactly the fraction `darkness` of the tile (to one stroke's area): the strokes reproduce the
// tone asked for — as tonal art maps add strokes until each level reaches its target tone.
layout(location = 0) out float coverage;
uniform usampler2D stroke_histogram;
uniform sampler2D stroke_index;
void main() {
    int i = int(gl_FragCoord.x);
    uint n = 0u;
    for (int k = 0; k <= i; ++k) n += texelFetch(stroke_histogram, ivec2(k, 0), 0).r;
    ivec2 size = textureSize(stroke_index, 0);
    coverage = float(n) / float(size.x * size.y);
}
