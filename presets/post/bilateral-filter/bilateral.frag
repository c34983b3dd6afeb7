#version 450
// Bilateral filtering (000_c9f7e5de708ecbb3.txt L3151-3183):
//   q_i = sum over j in N(i) of W_ij(I) p_j,   W_ij = G_s(|x_i - x_j|) G_r(|I_i - I_j|) / normalisation
// A Gaussian has only the spatial weight G_s and "is always blurry"; the bilateral filter also
// weighs by similarity of the range channel I: the colour itself (bilateral, I = p), or another
// image such as the depth buffer (joint bilateral, L3172-3177: "avoids bleeding in depth of
// field"). Radius 2 sigma_s. FORCE_GAUSSIAN drops the range weight.
// The guide is the colour's alpha (scene.frag): one fetch per tap.
// split (the live view): the display shows the noisy input left of the middle, so those pixels
// are not filtered (written 0; from 2 px left of the middle on they are).
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
            float w = exp(-float(x * x + y * y) / (2.0 * params.sigma_s * params.sigma_s));
#ifndef FORCE_GAUSSIAN
            float dr = params.mode == MODE_JOINT ? cj4.a - gi : params.mode == MODE_BILATERAL ? length(cj - ci) : 0.0;
            w *= exp(-dr * dr / (2.0 * params.sigma_r * params.sigma_r));
#endif
            sum += w * cj, wsum += w;
        }
    result = vec4(sum / wsum, 1.0);
}
