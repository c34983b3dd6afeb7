// What the texture-synthesis passes agree on: the output grows in square rings around its
// centre, from a 3x3 seed copied out of the source (Efros and Leung start from a 3x3 seed).
// Ring r = the texels at Chebyshev distance r from the centre; the seed is r <= 1. A texel's
// alpha records the ring that filled it (a8 = 1 for the seed, r for ring r, 0 = unknown), so
// ring r reads as known exactly the texels with 1 <= a8 < r: a texel of the same ring, written
// by another thread during the same dispatch, never counts, whatever the timing.
#ifndef SYNTH_COMMON_GLSL
#define SYNTH_COMMON_GLSL
#include "common/hash.glsl"

const ivec2 kSeedAt = ivec2(20, 20);   // source texel the seed is centred on

ivec2 synth_centre(ivec2 size) { return size / 2; }
int synth_ring(ivec2 p, ivec2 size) {
    ivec2 d = abs(p - synth_centre(size));
    return max(d.x, d.y);
}

// The growth order: ring by ring from ring 2, around each ring clockwise from its top-left
// corner (8 r slots; slots outside the image stay empty). Frame f fills the orders
// [f K, (f + 1) K), K = params.texels, so the live view spreads the work over frames; since a
// ring never reads itself the result does not depend on K.
int synth_ring_start(int r) { return 4 * r * (r - 1) - 8; }   // sum of 8 k, k = 2 .. r - 1
int synth_ring_of(int order) {
    int r = 2;
    while (synth_ring_start(r + 1) <= order) ++r;
    return r;
}
// The texel of an order (outside the image for the empty slots of a clipped ring).
ivec2 synth_texel(int order, ivec2 size) {
    int r = synth_ring_of(order);
    int pos = order - synth_ring_start(r);
    ivec2 d;
    if (pos <= 2 * r) d = ivec2(pos - r, -r);          // top edge, left to right
    else if (pos <= 4 * r) d = ivec2(r, pos - 3 * r);  // right edge, downwards
    else if (pos <= 6 * r) d = ivec2(5 * r - pos, r);  // bottom edge, right to left
    else d = ivec2(-r, 7 * r - pos);                   // left edge, upwards
    return synth_centre(size) + d;
}

// A 5x5 tile of random 8-bit colours, repeated: period 5.
vec3 periodic_tile(ivec2 p) {
    vec3 h = hash_pcg3(vec3(p % 5, 91.0));
    return floor(h * 255.0 + 0.5) / 255.0;
}
#endif
