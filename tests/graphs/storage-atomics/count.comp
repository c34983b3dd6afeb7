#version 450
layout(local_size_x = 8, local_size_y = 8) in;
layout(std430) buffer Counter { uint n; } counter;
layout(r32ui) uniform uimage2D hits;
void main() {
    atomicAdd(counter.n, 1u);
    imageAtomicAdd(hits, ivec2(0), 1u);
}
