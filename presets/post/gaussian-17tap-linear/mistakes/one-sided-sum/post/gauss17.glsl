// EXERCISE — the 17-tap Gaussian with linear lookups (002_644d46bdce7e5305.txt L871-895).
// This file shadows passes/post/gauss17.glsl. Fill in the three TODO blocks, then grade:
//     passlab run   post/gaussian-17tap-linear --exercise presets/post/gaussian-17tap-linear/exercise
//     passlab grade post/gaussian-17tap-linear --exercise presets/post/gaussian-17tap-linear/exercise
// Four symmetric pairs of bilinear lookups; each lookup sits between two texels i, i+1 so the
// hardware fetches both with the weights (1 - f) W and f W (f = the fractional offset).
#ifndef PASSLAB_GAUSS17_GLSL
#define PASSLAB_GAUSS17_GLSL

// The printed constants (L882-893): lookup offsets (in texels) and lookup weights W_i.
const float kGauss17Offset[4] = float[](0.6494988171273325, 2.405752812667325, 4.334747038826614, 6.27051066767145);
const float kGauss17Weight[4] = float[](0.22251469736395335, 0.1934401294345523, 0.06915657278613227, 0.013708153234290525);

// TODO 2: the sum of the weights of ALL the lookups one pass makes (L871-895: how many lookups
// does a pass make, and which weight does each carry?). Dividing by it makes a flat image stay
// flat; as printed it is not exactly 1.
const float kGauss17Sum = (0.22251469736395335 + 0.1934401294345523 + 0.06915657278613227 + 0.013708153234290525);

// 8 linear lookups along `step` (= direction / texture size) around uv.
vec4 gauss17_linear(sampler2D s, vec2 uv, vec2 step, bool renormalize) {
    vec4 sum = vec4(0.0);
    // TODO 1: for each of the 4 pairs i, add the bilinear lookups (textureLod, level 0) at
    // uv displaced by +offset_i and -offset_i texels along step, each weighted by W_i (L882-893):
    //     sum = sum_i W_i (c(uv + o_i step) + c(uv - o_i step))
    for (int i = 0; i < 4; ++i)
        sum += (textureLod(s, uv + step * kGauss17Offset[i], 0.0) + textureLod(s, uv - step * kGauss17Offset[i], 0.0)) * kGauss17Weight[i];
    return renormalize ? sum / kGauss17Sum : sum;
}

// The discrete weight of integer tap t (-7..7) implied by the lookups above.
float gauss17_discrete_weight(int t) {
    int a = abs(t);
    float w = 0.0;
    // TODO 3: invert the linear-lookup trick. A lookup of weight W at offset o = lo + f
    // (lo = floor(o)) returns (1 - f) c_lo + f c_(lo+1), so it gives texel lo a share and texel
    // lo + 1 another (which share goes to the nearer texel?). Add to w the share each of the 4
    // lookups gives to texel a. Tap 0 is special: the lookups on both sides of it each give it
    // a share, and the loop above only counts one side.
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
