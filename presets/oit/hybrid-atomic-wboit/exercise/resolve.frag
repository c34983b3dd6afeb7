#version 450
// EXERCISE — this file shadows the preset's resolve.frag for oit/hybrid-atomic-wboit only.
//     passlab run   presets/oit/hybrid-atomic-wboit --exercise presets/oit/hybrid-atomic-wboit/exercise
//     passlab grade presets/oit/hybrid-atomic-wboit --exercise presets/oit/hybrid-atomic-wboit/exercise
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
    // TODO (slots): front to back under, clearing each slot (L1800-1814)
    //   for i in 0..k-1: d = atomicExchange(kdepth.slot[base + i], 0xffffffffu); stop when d is 0xffffffff;
    //   q = kcolor.packed[base + i]: colour = (unpackHalf2x16(q.x), unpackHalf2x16(q.y)), emission from q.zw;
    //   result += ((rgb * a, a) + emission) * (1 - result.a)
    vec4 acc = texelFetch(tail_accum, p, 0);
    float r = texelFetch(tail_reveal, p, 0).r;
    vec4 tail = vec4(acc.rgb / max(acc.a, 1e-5), r);
    // TODO (tail): the tail's average colour with its coverage 1 - r, under what is in front
    //   result += (tail.rgb * (1 - r), 1 - r) * (1 - result.a). Compare the listing's vec4 form
    //   (L1834) with this one: which alpha does each leave for the final blend?
    color = result;
}
