#version 450
// Emission after the step: `rate` new particles, or as many as the dead stack holds (the pool
// never grows: a full system emits nothing rather than write past its capacity). Thread k takes
// the k-th slot from the top of the stack; `end` lowers the stack by the number taken, so no
// thread here changes counts.dead and every thread reads the same top.
layout(local_size_x = 64) in;
#include "particles/particle.glsl"
void main() {
    uint k = gl_GlobalInvocationID.x;
    uint n = min(uint(params.rate), counts.dead);
    if (k >= n) return;
    uint slot = dead_list.slot[counts.dead - 1u - k];
    PlParticle q;
    q.emit_id = counts.emitted + k;
    pl_birth(q.emit_id, q.x0, q.v0);
    q.x = q.x0; q.v = q.v0; q.age = 0u; q.alive = 1u; q.birth = counts.step;
    particles.p[slot] = q;
    alive_list.slot[atomicAdd(counts.alive, 1u)] = slot;
}
