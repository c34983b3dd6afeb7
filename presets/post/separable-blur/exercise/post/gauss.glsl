// EXERCISE — this file shadows passes/post/gauss.glsl for post/separable-blur only.
//     passlab run   post/separable-blur --exercise presets/post/separable-blur/exercise
//     passlab grade post/separable-blur --exercise presets/post/separable-blur/exercise
// 1D blur kernels along a direction, shared by the separable passes (fragment and compute).
// 000_c9f7e5de708ecbb3.txt L3020-3077: a 5x5 Gaussian needs 25 lookups; it is separable, so a
// 5x1 pass followed by a 1x5 pass gives the same result with 10; with bilinear filtering the
// 5 taps shrink to 3 lookups. The box blur of the listing takes 32 taps at (i - 16) + 0.5.
#ifndef PASSLAB_GAUSS_GLSL
#define PASSLAB_GAUSS_GLSL

// Binomial weights (1 4 6 4 1) / 16: the 5-tap Gaussian with sigma = 1.
const float kGauss5[5] = float[](1.0 / 16.0, 4.0 / 16.0, 6.0 / 16.0, 4.0 / 16.0, 1.0 / 16.0);

// Five discrete taps at integer texel offsets -2..2. `texel` = dir / size: one texel along the
// pass's direction (x in blur_x, y in blur_y).
vec4 gauss5_discrete(sampler2D s, vec2 uv, vec2 texel) {
    // TODO 1: the 5x1 filter (000_c9f7e5de708ecbb3.txt L3040-3044): the weighted sum of the five
    // texels at offsets -2, -1, 0, 1, 2 texels from uv, weights kGauss5. Run twice (along x,
    // then along y) it must equal the direct 5x5 product kernel w(i) w(j) of direct.frag.
    return texture(s, uv);
}

// The same kernel with 3 bilinear lookups (000 L3048-3049, "5x1 filter with 3 lookups").
vec4 gauss5_linear(sampler2D s, vec2 uv, vec2 texel) {
    // TODO 2: a LINEAR lookup between texels k and k + 1 at fraction t returns
    // (1 - t) T_k + t T_{k+1}. Merge the taps at -2 and -1 (weights 1/16, 4/16) into one lookup
    // at an offset between them, scaled so that both texels keep their own weight; the same for
    // +1 and +2; the centre tap stays. Work out the merged weight and the offset: the offset is
    // not the midpoint -1.5.
    return texture(s, uv);
}

// The listing's box blur: n taps at ((i - n/2) + 0.5) texels, weight 1/n.
vec4 box_blur(sampler2D s, vec2 uv, vec2 texel, int n) {
    vec4 c = vec4(0.0);
    for (int i = 0; i < n; ++i) c += texture(s, uv + texel * (float(i - n / 2) + 0.5));
    return c / float(n);
}

#endif
