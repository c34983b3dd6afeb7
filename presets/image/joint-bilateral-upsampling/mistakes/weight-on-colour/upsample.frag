#version 450
// Joint bilateral upsampling (Kopf et al. 2007; 000_c9f7e5de708ecbb3.txt L3244-3274, on PS4 Pro:
// "colour buffer as primary channel, edge buffer as secondary channel"). The colour at a
// full-resolution pixel p is a weighted mean of the 2x2 low-resolution colours around it:
//     c(p) = sum_q c_q s(p, q) r(g_p, g_q) / sum_q s(p, q) r(g_p, g_q)
// s = the bilinear (spatial) weight, r = the range weight computed on the GUIDE g, known at full
// resolution at p and at low resolution at q: r = [id_p == id_q] exp(-(z_p - z_q)^2 / (2 sigma^2)).
// A tap from another object gets no weight, so colours do not bleed across ID and depth edges.
// With a constant guide r = 1 and this is bilinear exactly. When no tap shares p's guide
// (an object thinner than a low-res texel), the bilinear mean is kept.
#include "taps.glsl"

layout(location = 0) out vec4 color;
uniform sampler2D low_color;
uniform sampler2D low_guide;
uniform sampler2D guide;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    ivec2 tap[4]; float w[4];
    jbu_taps(p, frame.target.xy, textureSize(low_color, 0), tap, w);
    vec2 gp = texelFetch(guide, p, 0).rg;
    // the bilinear colour at p, what the taps are compared with
    vec3 ref = vec3(0.0);
    for (int k = 0; k < 4; ++k) ref += w[k] * texelFetch(low_color, tap[k], 0).rgb;
    vec3 sum = vec3(0.0), bil = vec3(0.0);
    float wsum = 0.0;
    for (int k = 0; k < 4; ++k) {
        vec3 cq = texelFetch(low_color, tap[k], 0).rgb;
        vec2 gq = texelFetch(low_guide, tap[k], 0).rg;
        // range weight on the colour: a tap far from the local colour counts less (a bilateral filter)
        vec3 dc = cq - ref;
        float r = exp(-dot(dc, dc) / (2.0 * 0.1 * 0.1));
        sum += w[k] * r * cq;
        wsum += w[k] * r;
        bil += w[k] * cq;
    }
    color = vec4(wsum > 1e-6 ? sum / wsum : bil, 1.0);
}
