// TAA's sub-pixel jitter (000_c9f7e5de708ecbb3.txt L3437-3444): the projection is offset by
//   P[2][0] += (sx * 2 - 1) / width,  P[2][1] += (sy * 2 - 1) / height
// i.e. by (sx - 1/2, sy - 1/2) pixels, with (sx, sy) from the Halton(2, 3) sequence (UE4's
// choice, L3450-3453), 8 points cycled. Index 1.. (point 0 of a radical inverse is (0, 0)).
#ifndef PASSLAB_TAA_JITTER_GLSL
#define PASSLAB_TAA_JITTER_GLSL
float radical_inverse(int i, int base) {
    float inv = 1.0 / float(base), f = inv, r = 0.0;
    for (; i > 0; i /= base, f *= inv) r += f * float(i % base);
    return r;
}
vec2 halton23(int i) { return vec2(radical_inverse(i, 2), radical_inverse(i, 3)); }
// The jitter of frame `index`, in pixels (zero when off).
vec2 taa_jitter(int index, bool on) { return on ? halton23(index % 8 + 1) - 0.5 : vec2(0.0); }
#endif
