// 1D blur kernels along a direction, shared by the separable passes (fragment and compute).
// 000_c9f7e5de708ecbb3.txt L3020-3077: a 5x5 Gaussian needs 25 lookups; it is separable, so a
// 5x1 pass followed by a 1x5 pass gives the same result with 10; with bilinear filtering the
// 5 taps shrink to 3 lookups. The box blur of the listing takes 32 taps at (i - 16) + 0.5.
#ifndef PASSLAB_GAUSS_GLSL
#define PASSLAB_GAUSS_GLSL

// Binomial weights (1 4 6 4 1) / 16: the 5-tap Gaussian with sigma = 1.
const float kGauss5[5] = float[](1.0 / 16.0, 4.0 / 16.0, 6.0 / 16.0, 4.0 / 16.0, 1.0 / 16.0);

// Five discrete taps at integer texel offsets -2..2. `texel` = dir / size.
vec4 gauss5_discrete(sampler2D s, vec2 uv, vec2 texel) {
    vec4 c = vec4(0.0);
    for (int i = 0; i < 5; ++i) c += kGauss5[i] * texture(s, uv + float(i - 2) * texel);
    return c;
}

// The same kernel with 3 bilinear lookups: taps 0+1 (weights 1,4) merge into one lookup at
// offset -2 + 4/5 = -1.2 with weight 5/16, likewise on the other side; the centre stays.
vec4 gauss5_linear(sampler2D s, vec2 uv, vec2 texel) {
    const float w_side = 5.0 / 16.0, w_mid = 6.0 / 16.0, off = 1.2;
    return w_side * texture(s, uv - off * texel) + w_mid * texture(s, uv) +
           w_side * texture(s, uv + off * texel);
}

// The listing's box blur: n taps at ((i - n/2) + 0.5) texels, weight 1/n.
vec4 box_blur(sampler2D s, vec2 uv, vec2 texel, int n) {
    vec4 c = vec4(0.0);
    for (int i = 0; i < n; ++i) c += texture(s, uv + texel * (float(i - n / 2) + 0.5));
    return c / float(n);
}

#endif
