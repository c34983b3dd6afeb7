#version 450
// Per-pixel linked lists, resolve (000_c9f7e5de708ecbb3.txt L4304-4319, "Linked List
// Traversal": "render a fullscreen quad (or compute shader)"; for each pixel parse its list, sort
// the fragments and blend them back to front). The sort and blend are in sort_blend.glsl (the
// exercise). A compute pass, not a fullscreen quad: on lavapipe (Mesa 22.3) the fragment-shader
// version mis-sorted the pixels along the fullscreen quad's diagonal (a 2x2 quad straddling the
// two triangles), measured as 116 of 15360 pixels off the analytic reference by up to 0.45.
#include "oit/composite.glsl"
#include "sort_blend.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba16f) uniform writeonly image2D color;

struct Node { uint rgba; float depth; uint next; uint pad; };
layout(std430) readonly buffer Nodes { Node node[]; } nodes;
layout(r32ui) uniform readonly uimage2D heads;
uniform sampler2D opaque;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(color)))) return;
    int cap = clamp(params.max_frags, 1, MAX_FRAGS);
    // 0xffffffff ends the list; a dropped (overflowed) fragment was never linked, and the
    // length bound guards against a corrupt link.
    uint len = uint(nodes.node.length());
    for (uint i = imageLoad(heads, p).r, steps = 0u; i < len && steps < len; i = nodes.node[i].next, ++steps)
        ppll_insert(cap, nodes.node[i].depth, nodes.node[i].rgba);
    imageStore(color, p, vec4(ppll_blend(texelFetch(opaque, p, 0).rgb), 1.0));
}
