#version 450
// Baked (runs on the first frame and again when a param changes): every slot dead and on the
// dead stack, the clock at 0. alive + dead = capacity from here on (L3804-3808: particles
// "die" after some time and their storage is reused).
layout(local_size_x = 64) in;
#include "particles/particle.glsl"
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i == 0u) { counts.alive = 0u; counts.dead = uint(params.capacity); counts.step = 0u; counts.emitted = 0u; }
    if (i >= uint(params.capacity)) return;
    particles.p[i].alive = 0u;
    particles.p[i].age = 0u;
    dead_list.slot[i] = uint(params.capacity) - 1u - i;   // pop order: slot 0 first
}
