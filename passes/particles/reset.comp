#version 450
// Baked (runs on the first frame and again when a param changes): every slot dead and on the
// dead stack, the clock at 0. alive + dead = capacity from here on (L3804-3808: particles
// "die" after some time and their storage is reused).
//
// With params.prewarm the system starts as if it had already run `life` steps: the particles of
// those steps are placed by the state-less closed form (the state-full system can start from
// any time the state-less one describes), so the first frame already shows a full fountain.
layout(local_size_x = 64) in;
#include "particles/particle.glsl"
void main() {
    uint i = gl_GlobalInvocationID.x;
    uint cap = uint(params.capacity), rate = uint(params.rate), life = uint(params.life);
    uint warm = params.prewarm ? min(rate * life, cap) : 0u;    // slots alive after the warm-up
    if (i == 0u) {
        counts.alive = warm; counts.dead = cap - warm;
        counts.step = params.prewarm ? life : 0u; counts.emitted = warm;
    }
    if (i >= cap) return;
    particles.p[i].alive = 0u;
    particles.p[i].age = 0u;
    if (i < warm) {
        // emission id i, born in step i / rate of the warm-up; after the last warm-up step its
        // age is (life - 1) - birth, and x, v are those of that many fixed steps.
        PlParticle q;
        q.emit_id = i;
        q.birth = i / rate;
        q.age = life - 1u - q.birth;
        pl_birth(i, q.x0, q.v0);
        q.x = pl_stateless_position(q.x0, q.v0, q.age, params.dt);
        q.v = q.v0 + params.gravity * (float(q.age) * params.dt);
        q.alive = 1u;
        particles.p[i] = q;
        alive_list.slot[i] = i;
    } else {
        dead_list.slot[i - warm] = cap - 1u - (i - warm);   // pop order: slot `warm` first
    }
}
