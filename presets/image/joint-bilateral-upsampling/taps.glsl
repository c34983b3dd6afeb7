// The 2x2 low-resolution texels around a full-resolution pixel and their bilinear weights,
// shared by the bilinear reference and the joint bilateral upsampling so they use the same taps
// (the hardware's bilinear filter has 8-bit weights on lavapipe: not a 1e-4 reference).
#ifndef JBU_TAPS_GLSL
#define JBU_TAPS_GLSL

// p: full-resolution pixel, full/low: sizes. Tap k (0..3) at base + (k & 1, k >> 1), clamped.
void jbu_taps(ivec2 p, vec2 full, ivec2 low, out ivec2 tap[4], out float w[4]) {
    vec2 s = (vec2(p) + 0.5) * vec2(low) / full - 0.5;   // position in low-res texel units
    ivec2 base = ivec2(floor(s));
    vec2 f = s - floor(s);
    for (int k = 0; k < 4; ++k) {
        ivec2 o = ivec2(k & 1, k >> 1);
        tap[k] = clamp(base + o, ivec2(0), low - 1);
        w[k] = (o.x == 1 ? f.x : 1.0 - f.x) * (o.y == 1 ? f.y : 1.0 - f.y);
    }
}
#endif
