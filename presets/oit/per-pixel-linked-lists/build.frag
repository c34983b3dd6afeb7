#version 450
// Per-pixel linked lists, build pass (000_c9f7e5de708ecbb3.txt L4224-4302, "Linked List
// Creation"): every transparent fragment that passes the depth test against the opaque scene
// takes the next free node from the atomic counter, stores (colour, depth, next) there and
// becomes its pixel's list head: next = atomicExchange(head, idx). The start offset buffer
// ("Screen-sized: width * height * sizeof(UINT32)", "Initialized to magic value", L4247-4253) is the
// r32ui image `heads`, cleared to 0xffffffff every frame.
// Early fragment tests: the depth test must reject occluded fragments before they append.
layout(early_fragment_tests) in;
layout(location = 0) flat in vec4 v_color;

struct Node { uint rgba; float depth; uint next; uint pad; };   // 16 bytes, std430
layout(std430) buffer Nodes { Node node[]; } nodes;              // "Fragment and Link Buffer"
layout(std430) buffer Count { uint n; } count;                   // the append counter
layout(r32ui) uniform coherent uimage2D heads;                   // "Start Offset Buffer"

void main() {
    uint idx = atomicAdd(count.n, 1u);
    // The buffer "must be large enough to store all fragments" (L4237): when it is not, the
    // counter runs past the capacity (the host reports it) and the fragment is dropped, never
    // written out of bounds.
    if (idx >= uint(nodes.node.length())) return;
    uint prev = imageAtomicExchange(heads, ivec2(gl_FragCoord.xy), idx);
    nodes.node[idx] = Node(packUnorm4x8(v_color), gl_FragCoord.z, prev, 0u);
}
