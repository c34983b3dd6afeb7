#version 450
// EXERCISE — bilateral and joint bilateral filtering (000_c9f7e5de708ecbb3.txt L3151-3183).
// Fill in the four TODO blocks, then check your work against the reference:
//     passlab run   post/bilateral-filter --exercise presets/post/bilateral-filter/exercise
//     passlab grade post/bilateral-filter --exercise presets/post/bilateral-filter/exercise
//   q_i = sum over j in N(i) of W_ij(I) p_j,   W_ij = G_s(|x_i - x_j|) G_r(|I_i - I_j|) / normalisation
// A Gaussian has only the spatial weight G_s; the bilateral filter also weighs by similarity of
// the range channel I: the colour itself (bilateral, I = p), or another image such as the
// depth buffer (joint bilateral, L3172-3177). Radius 2 sigma_s. FORCE_GAUSSIAN (the `gaussian`
// pass the tests compare with) drops the range weight.
// The guide (depth) is the colour's alpha (scene.frag): one fetch per tap.
// split (the live view): pixels left of the middle are not shown filtered, so not filtered.
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 result;
uniform sampler2D color;
void main() {
    if (params.split && gl_FragCoord.x + 2.0 < 0.5 * frame.resolution.x) {
        result = vec4(0.0);
        return;
    }
    ivec2 px = ivec2(gl_FragCoord.xy), last = textureSize(color, 0) - 1;
    int r = int(ceil(2.0 * params.sigma_s));
    vec4 ci4 = texelFetch(color, px, 0);
    vec3 ci = ci4.rgb;
    float gi = ci4.a;
    vec3 sum = vec3(0.0);
    float wsum = 0.0;
    for (int y = -r; y <= r; ++y)
        for (int x = -r; x <= r; ++x) {
            ivec2 q = clamp(px + ivec2(x, y), ivec2(0), last);
            vec4 cj4 = texelFetch(color, q, 0);
            vec3 cj = cj4.rgb;
            // TODO 1: the spatial weight G_s of the tap at offset (x, y): a Gaussian of the
            // distance |x_i - x_j| with standard deviation params.sigma_s (pixels).
            float w = 0.0;
#ifndef FORCE_GAUSSIAN
            // TODO 2: the range difference I_j - I_i (L3158-3162, L3172-3177): for MODE_JOINT
            // the guide (the depth in the alpha channel), for MODE_BILATERAL the colour itself
            // (a distance between two colours), for the Gaussian mode none.
            float dr = 0.0;
            // TODO 3: multiply w by the range weight G_r(dr): a Gaussian of dr with standard
            // deviation params.sigma_r (in the range channel's units).
#endif
            // TODO 4: accumulate the weighted colour in sum and the weight W_ij in wsum.
        }
    // TODO 4 (continued): q_i is the weighted sum divided by the normalisation (the sum of the
    // weights actually applied). Placeholder: the unfiltered colour.
    result = vec4(ci, 1.0);
}
