#version 450
// Hybrid atomic loop + weighted blended OIT, pass two (002_644d46bdce7e5305.txt L1719-1782,
// oitPassTwo): a fragment among the k nearest (binary search, oit/kbuffer.glsl) stores its colour
// in its slot as two packed RGBA16F values (xy: the alpha-blended colour, zw: the emission colour,
// L1688, L1740-1748) and adds nothing to the tail; any other fragment goes to the weighted
// blended tail (oit/wboit.glsl): accum += (rgb * a, a) * w (blend one, one) and the revealage
// *= (1 - a) (blend zero, one_minus_src_color, cleared to 1; the listing does not print the tail's
// blend state, this is the one its resolve's `* (1 - alpha)` needs).
// The listing's second branch (emission in the tail, faked with the rescale weight 1e-3,
// L1770-1781) is not reproduced: the scene's emission reaches the slots only.
#include "oit/kbuffer.glsl"
#include "oit/wboit.glsl"
layout(early_fragment_tests) in;
layout(location = 0) flat in vec4 v_color;
layout(location = 0) out vec4 accum;
layout(location = 1) out vec4 reveal;
layout(std430) writeonly buffer KColor { uvec4 packed[]; } kcolor;

void main() {
    vec4 c = v_color;
    if (params.mono) c.rgb = params.mono_rgb;
    vec4 emission = vec4(c.rgb * params.emission, 0.0);
    int i = oit_kbuffer_find();
    accum = vec4(0.0); reveal = vec4(0.0);   // a = 0: adds nothing, multiplies the revealage by 1
    if (i >= 0) {
        kcolor.packed[oit_kbuffer_base() + i] = uvec4(packHalf2x16(c.rg), packHalf2x16(c.ba),
                                                      packHalf2x16(emission.rg), packHalf2x16(emission.ba));
    } else {
        float w = oit_wboit_weight(c, gl_FragCoord.z * params.depth_range);
        accum = vec4(c.rgb * c.a, c.a) * w;
        reveal = vec4(c.a);
    }
}
