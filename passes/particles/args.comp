#version 450
// The indirect draw's arguments (VkDrawIndirectCommand): 6 vertices (a billboard) per particle;
// the instance count is the alive count the GPU just computed, so the host never reads it back.
// State-less: every emission id of the last `life` steps, `rate` per step (the state-full system
// holds the same particles when capacity >= rate * life).
layout(local_size_x = 1) in;
#define PL_PARTICLE_ACCESS readonly
#include "particles/particle.glsl"
layout(std430) writeonly buffer DrawArgs { uint vertex_count; uint instance_count; uint first_vertex; uint first_instance; } draw_args;
void main() {
    draw_args.vertex_count = 6u;
    draw_args.instance_count = params.mode == MODE_STATELESS ? uint(params.rate * params.life) : counts.alive;
    draw_args.first_vertex = 0u;
    draw_args.first_instance = 0u;
}
