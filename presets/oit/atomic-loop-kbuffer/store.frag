#version 450
// Atomic loop k-buffer, pass two (002_644d46bdce7e5305.txt L1608-1647): "Insert color based on
// depth with binary search"; a fragment not among the k nearest is tail-blended: this pass's
// colour target is the opaque image with the over blend, so the tail lands behind every kept
// layer, in primitive order ("Tail blend is stable (primitive-order obeyed)", L1611): exact while
// the depth complexity is <= k, order dependent in the tail beyond it. `tail` counts tail
// fragments (a statistic, not an overflow: the k slots cannot overflow).
#include "oit/kbuffer.glsl"
layout(early_fragment_tests) in;
layout(location = 0) flat in vec4 v_color;
layout(location = 0) out vec4 color;
layout(std430) writeonly buffer KColor { uint rgba[]; } kcolor;   // packUnorm4x8, one per slot
layout(std430) buffer Tail { uint fragments; } tail;

void main() {
    int i = oit_kbuffer_find();
    if (i >= 0) {
        kcolor.rgba[oit_kbuffer_base() + i] = packUnorm4x8(v_color);
        color = vec4(0.0);   // alpha 0: the over blend leaves the tail untouched
    } else {
        atomicAdd(tail.fragments, 1u);
        color = v_color;
    }
}
