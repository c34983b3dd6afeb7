// Interleaved progressive tracing: the live view traces one pixel of every k x k tile per frame
// (k = params.interleave, rounded up to a power of two), visiting the tile's pixels in Bayer order, so a frame
// costs 1/k^2 of a full one and the picture fills in evenly. Pixel p is traced on the frames
// n = phase(p) (mod k^2) after an accumulation reset; on its j-th traced frame it takes the
// samples j * spp .. j * spp + spp - 1, the same sample indices as with k = 1: interleaving
// changes when a pixel's samples are taken, never which.
#ifndef PASSLAB_GI_PT_INTERLEAVE_GLSL
#define PASSLAB_GI_PT_INTERLEAVE_GLSL

// k: params.interleave rounded up to a power of two (the trace pass dispatches
// ceil(view / params.interleave) threads, at least ceil(view / k); the extra ones fall outside).
int pt_interleave() { return 1 << (findMSB(clamp(params.interleave, 1, 8) - 1) + 1); }

// The Bayer index of cell c of a 2^bits x 2^bits tile: 2 (x ^ y) + y per bit, the lowest bits
// most significant (2x2: [[0, 2], [3, 1]]).
uint pt_bayer(uvec2 c, int bits) {
    uint v = 0u;
    for (int i = 0; i < bits; ++i) {
        uint x = (c.x >> uint(i)) & 1u, y = (c.y >> uint(i)) & 1u;
        v |= (2u * (x ^ y) + y) << uint(2 * (bits - 1 - i));
    }
    return v;
}

// The cell of Bayer index v (the inverse of pt_bayer).
uvec2 pt_bayer_cell(uint v, int bits) {
    uvec2 c = uvec2(0u);
    for (int i = 0; i < bits; ++i) {
        uint d = (v >> uint(2 * (bits - 1 - i))) & 3u, y = d & 1u, x = (d >> 1u) ^ y;
        c |= uvec2(x, y) << uint(i);
    }
    return c;
}

uint pt_phase(ivec2 p) {
    int k = pt_interleave();
    return pt_bayer(uvec2(p % k), findMSB(k));
}

// Whether pixel p has been traced at least once by frame n of the accumulation.
bool pt_reached(ivec2 p, uint n) { return n >= pt_phase(p); }

// The pixel that invocation `id` of the packed trace grid (ceil(view / k) threads) traces on
// frame n: one per tile, all at the same cell, so the traced invocations are contiguous and no
// SIMD lane idles.
ivec2 pt_traced_pixel(ivec2 id, uint n) {
    int k = pt_interleave();
    return id * k + ivec2(pt_bayer_cell(n % uint(k * k), findMSB(k)));
}

#endif
