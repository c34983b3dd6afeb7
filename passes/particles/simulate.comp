#version 450
// One fixed step for every slot (000_c9f7e5de708ecbb3.txt L3795-3808, L3824-3826: one update
// method for all, lifetime, gravity). A particle that has lived `life` steps dies: its slot is
// pushed on the dead stack. A survivor is integrated (pl_step: semi-implicit Euler) and appended
// to the alive list, which the draw reads through an indirect instance count.
layout(local_size_x = 64) in;
#include "particles/particle.glsl"
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(params.capacity) || particles.p[i].alive == 0u) return;
    PlParticle q = particles.p[i];
    q.age += 1u;
    if (q.age >= uint(params.life)) {
        particles.p[i].alive = 0u;
        dead_list.slot[atomicAdd(counts.dead, 1u)] = i;
        return;
    }
    pl_step(q.x, q.v, params.dt);
    particles.p[i] = q;
    alive_list.slot[atomicAdd(counts.alive, 1u)] = i;
}
