// Interleaved sampling (002_644d46bdce7e5305.txt L2333-2336: "Bayer matrix interleaved sample ray
// offset jittering with a cross-bilateral blur filter"; 000_c9f7e5de708ecbb3.txt L5277-5285):
// neighbouring pixels start their march at different offsets inside a step, so a 4 x 4 tile
// together takes 16 x the samples; a blur over the tile, stopped at depth edges, trades the
// tile's resolution for those samples.
#ifndef PASSLAB_VOLUMETRIC_INTERLEAVE_GLSL
#define PASSLAB_VOLUMETRIC_INTERLEAVE_GLSL

// The 4 x 4 Bayer (ordered-dither) matrix, values 0..15: each value once per tile, and any two
// consecutive values far apart in the tile.
float bayer4(ivec2 p) {
    const float m[16] = float[](0.0, 8.0, 2.0, 10.0,
                                12.0, 4.0, 14.0, 6.0,
                                3.0, 11.0, 1.0, 9.0,
                                15.0, 7.0, 13.0, 5.0);
    ivec2 q = p & 3;
    return m[q.y * 4 + q.x];
}

// The ray offset of pixel p, in steps: one of {0..15}/16, plus 1/32 so the 16 offsets sit at the
// centres of 16 equal sub-steps (their mean is 1/2, a midpoint rule over the tile).
float interleave_offset(ivec2 p) {
    return bayer4(p) / 16.0 + 1.0 / 32.0;
}
#endif
