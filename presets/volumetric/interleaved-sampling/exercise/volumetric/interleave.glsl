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
    // TODO 1 (002_644d46bdce7e5305.txt L2333-2336, "Bayer matrix interleaved sample ray offset
    // jittering"): the 4 x 4 Bayer matrix at (p mod 4); each of 0..15 exactly once per tile, built
    // recursively from [0 2; 3 1]: M_2n = [4 M_n, 4 M_n + 2; 4 M_n + 3, 4 M_n + 1].
    return 0.0;
}

// The ray offset of pixel p, in steps: one of {0..15}/16, plus 1/32 so the 16 offsets sit at the
// centres of 16 equal sub-steps (their mean is 1/2, a midpoint rule over the tile).
float interleave_offset(ivec2 p) {
    return bayer4(p) / 16.0 + 1.0 / 32.0;
}
#endif
