#version 450
// EXERCISE — this file shadows the preset's layer.vert (TODO 1-2); layer.frag next to it holds
// TODO 3.
//     passlab run   fundamentals/depth-test --exercise presets/fundamentals/depth-test/exercise
//     passlab grade fundamentals/depth-test --exercise presets/fundamentals/depth-test/exercise
// Layer gl_InstanceIndex (one quad of 6 vertices): a rectangle offset diagonally per layer (or
// the whole view with params.full), at a depth given by its rank. front_to_back: instance 0 is
// the nearest; back_to_front: instance 0 is the farthest. Instances past params.layers, and the
// whole draw when VISIBLE is false, are hidden.
layout(location = 0) flat out int v_rank;
void main() {
    int i = gl_InstanceIndex, n = params.layers;
    // TODO 1: the layer's depth rank, 0 = nearest, n - 1 = farthest, from its submission index i
    // and params.order: front_to_back submits the nearest first, back_to_front the farthest
    // first (ORDER_FRONT_TO_BACK / ORDER_BACK_TO_FRONT).
    int rank = 0;
    const vec2 corners[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));
    vec2 c = corners[gl_VertexIndex];
    // Layers step down-right as they get farther, so each shows a strip of itself.
    vec2 lo = params.full ? vec2(-1.0) : vec2(-0.85) + vec2(0.09) * float(rank);
    vec2 hi = params.full ? vec2(1.0) : lo + vec2(1.0, 1.0);
    // TODO 2: the layer's depth z in NDC (Vulkan: [0, 1]), from its rank: the n layers evenly
    // spaced in [0.1, 0.9), 0.8 / n apart, rank 0 at one end (z = 0.1) or the other. The depth
    // test is "less" with the buffer cleared to 1 (000 L177-185): which end of the range is
    // near the eye, and so which rank gets z = 0.1?
    float z = 0.5;
    v_rank = rank;
    gl_Position = vec4(mix(lo, hi, c), z, 1.0);
    if (i >= n || !(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
