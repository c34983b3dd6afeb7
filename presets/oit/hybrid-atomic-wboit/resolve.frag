#version 450
// Hybrid resolve (002_644d46bdce7e5305.txt L1786-1840, oitResolve), drawn with the blend
// ONE, ONE_MINUS_SRC_ALPHA onto the opaque colour (L1790): the output is premultiplied.
//   1. out = (0, 0, 0, 0) (L1796-1798)
//   2. the k slots front to back with the under operator, each slot cleared for the next frame by
//      atomicExchange(slot, 0xffffffff) (L1800-1814): out += (rgb * a, a) + emission) * (1 - out.a)
//   3. the weighted blended tail, behind every slot: tail = (rgb / max(a, 1e-5), revealage r)
//      (L1816-1828), then (L1830-1835, flagged "TO-DO: Check if it is correct in this way"):
//        listing:   out += (tail * (1 - tail.a)) * (1 - out.a)     as vec4: the alpha gains
//                   r * (1 - r) * (1 - out.a), not the tail's coverage (1 - r) * (1 - out.a), so the
//                   opaque colour shows through too much (r = 0.5: 0.25 instead of 0.5);
//        corrected: out += vec4(tail.rgb * (1 - r), 1 - r) * (1 - out.a).
//      params.tail picks one (`tail-composite-checked` shows the listing's fails).
// The listing declares `vec4 l0outputColor` (L1798, used in step 2) but steps 3 and the return use
// `lOutputColor` (L1834-1839): as printed it does not compile; one variable, `result`, here.
#include "oit/kbuffer.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(std430) readonly buffer KColor { uvec4 packed[]; } kcolor;
uniform sampler2D tail_accum;
uniform sampler2D tail_reveal;

void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 result = vec4(0.0);
    int base = oit_kbuffer_base();
    // front to back under, clearing each slot (L1800-1814)
    for (int i = 0; i < params.k; ++i) {
        uint d = atomicExchange(kdepth.slot[base + i], 0xffffffffu);
        if (d == 0xffffffffu) break;
        uvec4 q = kcolor.packed[base + i];
        vec4 c = vec4(unpackHalf2x16(q.x), unpackHalf2x16(q.y));
        vec4 e = vec4(unpackHalf2x16(q.z), unpackHalf2x16(q.w));
        result += (vec4(c.rgb * c.a, c.a) + e) * (1.0 - result.a);
    }
    vec4 acc = texelFetch(tail_accum, p, 0);
    float r = texelFetch(tail_reveal, p, 0).r;
    vec4 tail = vec4(acc.rgb / max(acc.a, 1e-5), r);
    // the tail's average colour with its coverage 1 - r, under what is in front
    if (params.tail == TAIL_LISTING) result += (tail * (1.0 - tail.a)) * (1.0 - result.a);
    else result += vec4(tail.rgb * (1.0 - r), 1.0 - r) * (1.0 - result.a);
    color = result;
}
