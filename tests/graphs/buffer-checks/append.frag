#version 450
// Per-pixel linked lists (the OIT A-buffer): every fragment takes a node index from the atomic
// counter in word 0 of `nodes`, and, when the index is below the capacity, links the node in
// front of its pixel's list (`heads`, cleared to 0xffffffff = end of list every frame). Run
// `params.layers` times: each pixel's list then holds `layers` nodes.
layout(location = 0) out vec4 color;

struct Node { uint pixel; uint next; };
layout(std430) buffer Nodes { uint count; uint pad; Node node[]; } nodes;
layout(std430) buffer Heads { uint head[]; } heads;

void main() {
    uvec2 p = uvec2(gl_FragCoord.xy);
    uint pixel = p.y * uint(frame.resolution.x) + p.x;
    uint idx = atomicAdd(nodes.count, 1u);
    // Overflow must be detected, never written out of bounds: the host compares the counter with
    // the declared capacity after the frame.
    if (idx < uint(nodes.node.length())) {
        uint prev = atomicExchange(heads.head[pixel], idx);
        nodes.node[idx] = Node(pixel, prev);
    }
    color = vec4(float(idx % 256u) / 255.0, 0.0, 0.0, 1.0);
}
