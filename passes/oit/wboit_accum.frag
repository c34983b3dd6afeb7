#version 450
// Weighted blended OIT, accumulation (002_644d46bdce7e5305.txt L1760-1768; oit/wboit.glsl), the
// accumulate pass of weighted-blended and of colored-blended's test-only check:
// one geometry pass in any order, two targets with order-independent blends:
//   accum  += (rgb * a, a) * w          blend one, one (additive)
//   reveal *= (1 - a)                   blend zero, one_minus_src_color (multiplicative), cleared to 1
// The weight's z is the view-space distance: NDC depth times params.depth_range (the listing's
// constants assume distances in scene units up to ~4096).
#include "oit/wboit.glsl"
layout(early_fragment_tests) in;
layout(location = 0) flat in vec4 v_color;
layout(location = 0) out vec4 accum;
layout(location = 1) out vec4 reveal;

void main() {
    vec4 c = v_color;
    if (params.mono) c.rgb = params.mono_rgb;   // equal colours: the case WBOIT gets exactly right
    float w = oit_wboit_weight(c, gl_FragCoord.z * params.depth_range);
    // L1766 "vec4(rgb * a, a) * weight"; the revealage factor is a
    accum  = vec4(c.rgb * c.a, c.a) * w;
    reveal = vec4(c.a);
}
