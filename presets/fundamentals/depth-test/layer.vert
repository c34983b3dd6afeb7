#version 450
// Layer gl_InstanceIndex (one quad of 6 vertices): a rectangle offset diagonally per layer (or
// the whole view with params.full), at a depth given by its rank. front_to_back: instance 0 is
// the nearest; back_to_front: instance 0 is the farthest. Instances past params.layers, and the
// whole draw when VISIBLE is false, are hidden.
layout(location = 0) flat out int v_rank;
void main() {
    int i = gl_InstanceIndex, n = params.layers;
    int rank = params.order == ORDER_FRONT_TO_BACK ? i : n - 1 - i;  // 0 = nearest
    const vec2 corners[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(1, 1), vec2(0, 0), vec2(1, 1), vec2(0, 1));
    vec2 c = corners[gl_VertexIndex];
    // Layers step down-right as they get farther, so each shows a strip of itself.
    vec2 lo = params.full ? vec2(-1.0) : vec2(-0.85) + vec2(0.09) * float(rank);
    vec2 hi = params.full ? vec2(1.0) : lo + vec2(1.0, 1.0);
    float z = 0.1 + 0.8 * float(rank) / float(max(n, 1));
    v_rank = rank;
    gl_Position = vec4(mix(lo, hi, c), z, 1.0);
    if (i >= n || !(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
