// The "separate linear interpolator optimized 17x17 gaussian blur" of
// 002_644d46bdce7e5305.txt L871-895 (also used by its lens flare), and the discrete kernel it
// stands for. Four symmetric pairs of bilinear lookups; each lookup sits between two texels i,
// i+1 so the hardware fetches both with the weights (1 - f) W and f W (f = the fractional
// offset). Recovering those discrete weights from the printed constants gives a Gaussian of
// sigma ~ 2.56 over taps -7..7 (centre 0.15598 = twice the share of tap 0 in the first pair).
// As printed the weights sum to 2 x 0.49882 = 0.99764: every pass loses 0.24% of the energy;
// `renormalize` divides it back.
#ifndef PASSLAB_GAUSS17_GLSL
#define PASSLAB_GAUSS17_GLSL

const float kGauss17Offset[4] = float[](0.6494988171273325, 2.405752812667325, 4.334747038826614, 6.27051066767145);
const float kGauss17Weight[4] = float[](0.22251469736395335, 0.1934401294345523, 0.06915657278613227, 0.013708153234290525);
const float kGauss17Sum = 2.0 * (0.22251469736395335 + 0.1934401294345523 + 0.06915657278613227 + 0.013708153234290525);

// 8 linear lookups along `step` (= direction / texture size) around uv.
vec4 gauss17_linear(sampler2D s, vec2 uv, vec2 step, bool renormalize) {
    vec4 sum = vec4(0.0);
    for (int i = 0; i < 4; ++i)
        sum += (textureLod(s, uv + step * kGauss17Offset[i], 0.0) + textureLod(s, uv - step * kGauss17Offset[i], 0.0)) * kGauss17Weight[i];
    return renormalize ? sum / kGauss17Sum : sum;
}

// The discrete weight of integer tap t (-7..7) implied by the lookups above.
float gauss17_discrete_weight(int t) {
    int a = abs(t);
    float w = 0.0;
    for (int i = 0; i < 4; ++i) {
        float lo = floor(kGauss17Offset[i]), f = kGauss17Offset[i] - lo;
        if (a == int(lo)) w += (1.0 - f) * kGauss17Weight[i];
        if (a == int(lo) + 1) w += f * kGauss17Weight[i];
    }
    return a == 0 ? 2.0 * w : w;  // tap 0 gets a share from the lookup on each side
}

// The same filter with 15 texel fetches (texelFetch, no filtering), clamped at the border.
vec4 gauss17_discrete(sampler2D s, ivec2 p, ivec2 dir, bool renormalize) {
    ivec2 last = textureSize(s, 0) - 1;
    vec4 sum = vec4(0.0);
    for (int t = -7; t <= 7; ++t) sum += texelFetch(s, clamp(p + t * dir, ivec2(0), last), 0) * gauss17_discrete_weight(t);
    return renormalize ? sum / kGauss17Sum : sum;
}
#endif
