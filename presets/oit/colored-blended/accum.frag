#version 450
// Colored blended OIT, accumulation (McGuire 2015, casual-effects.blogspot.de/2015/03/
// colored-blended-order-independent.html, named as the drop-in for the hybrid's tail by
// 002_644d46bdce7e5305.txt L1844-1846). Weighted blended OIT (oit/wboit.glsl) with a transmission
// per channel instead of one alpha: each quad reflects rgb * a (premultiplied) and transmits
//   t = 1 - a * (1 - colored * rgb)    per channel: grey 1 - a at colored = 0; at colored = 1 a
//                                       channel the quad's colour holds passes unfiltered
// Its net coverage is a' = 1 - avg(t) ("premultipliedReflect.a *= 1 - avg(transmit)" in the post,
// with coverage 1), which weights and normalises the reflected colour as in WBOIT:
//   accum    += (rgb * a, a') * w          blend one, one
//   reveal   *= (1 - a')                    blend zero, one_minus_src_color, cleared to 1
//   transmit *= t                           blend zero, src_color, cleared to 1 (per channel)
// With grey transmission a' = a, t = 1 - a and transmit = reveal: exactly weighted-blended.
#include "oit/wboit.glsl"
layout(early_fragment_tests) in;
layout(location = 0) flat in vec4 v_color;
layout(location = 0) out vec4 accum;
layout(location = 1) out vec4 reveal;
layout(location = 2) out vec4 transmit;

void main() {
    vec4 c = v_color;
    vec3 t = 1.0 - c.a * (1.0 - params.colored * c.rgb);
    float coverage = 1.0 - (t.r + t.g + t.b) / 3.0;
    float w = oit_wboit_weight(vec4(c.rgb, coverage), gl_FragCoord.z * params.depth_range);
    accum = vec4(c.rgb * c.a, coverage) * w;
    reveal = vec4(coverage);
    transmit = vec4(t, 1.0);
}
