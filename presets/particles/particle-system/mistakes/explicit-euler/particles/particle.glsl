// A GPU particle system with a fixed step: the state, its buffers and the two ways to know where
// a particle is.
//
// 000_c9f7e5de708ecbb3.txt L3741-3837: every particle of a system shares one update method
// (L3795-3800), its parameters change over time (location, speed, lifetime) and it "dies" after
// some time (L3804-3808); the seed's record is `struct particle { float t; float v; float x, y, z;
// float xd, yd, zd; float alpha; }` (L3812-3820: lifetime, speed, position, direction, fade).
// Here speed and direction are one velocity vector, the lifetime is counted in fixed steps, alpha
// is derived from the age when drawn, and the birth state (x0, v0, birth step) is kept so the
// state-less closed form and the analytic parabola can be checked against the stepped state.
//
// State-full vs state-less (L3750): a state-full particle is integrated step by step and
// needs storage (this file's buffers); a state-less one is a closed-form function of its
// emission id and the time, so it needs none — but it cannot react to anything (no collision,
// no interaction, L3826-3830). With constant gravity both exist here and must agree.
//
// Include with PL_PARTICLE_ACCESS defined as `readonly` in passes that only read.
#ifndef PASSLAB_PARTICLE_GLSL
#define PASSLAB_PARTICLE_GLSL
#include "common/hash.glsl"

#ifndef PL_PARTICLE_ACCESS
#define PL_PARTICLE_ACCESS
#endif

// std430, 64 bytes (buffer checks: stride 64; field 12 emit_id, 28 age, 44 alive, 60 birth).
struct PlParticle {
    vec3 x;  uint emit_id;   // position; global emission number (seeds the birth state)
    vec3 v;  uint age;       // velocity; fixed steps since birth
    vec3 x0; uint alive;     // birth position; 1 = alive, 0 = dead (in the dead list)
    vec3 v0; uint birth;     // birth velocity; the step it was born in
};

layout(std430) PL_PARTICLE_ACCESS buffer Particles { PlParticle p[]; } particles;
// The bookkeeping, one struct so a buffer check sums alive + dead (words 0 and 1).
layout(std430) PL_PARTICLE_ACCESS buffer Counts {
    uint alive;     // entries of alive_list this step
    uint dead;      // entries of dead_list (a stack of free slots)
    uint step;      // fixed steps simulated since the reset (the GPU's clock)
    uint emitted;   // particles emitted since the reset
} counts;
layout(std430) PL_PARTICLE_ACCESS buffer AliveList { uint slot[]; } alive_list;
layout(std430) PL_PARTICLE_ACCESS buffer DeadList { uint slot[]; } dead_list;

// Emission: a fountain. Every random number comes from the emission id through an integer hash
// (common/hash.glsl), so the state-full and the state-less system emit the same particles.
void pl_birth(uint e, out vec3 x0, out vec3 v0) {
    vec3 r = vec3(pcg3d(uvec3(e, 0x9e3779b9u, 0x85ebca6bu))) * (1.0 / 4294967296.0);
    float phi = 6.2831853 * r.x;
    float spread = params.spread * sqrt(r.y);          // uniform over a disc of directions
    x0 = params.emitter + 0.05 * vec3(cos(phi), 0.0, sin(phi)) * r.y;
    v0 = params.speed * (0.85 + 0.3 * r.z) * normalize(vec3(spread * cos(phi), 1.0, spread * sin(phi)));
}

// One fixed step of semi-implicit (symplectic) Euler: velocity first, then the position with the
// new velocity. After n steps from (x0, v0): x_n = x0 + v0 n dt + g dt^2 n(n+1)/2, i.e. the
// parabola x0 + v0 t + g t^2 / 2 plus exactly g t dt / 2 (t = n dt).
void pl_step(inout vec3 x, inout vec3 v, float dt) {
    x += v * dt;                 // explicit (forward) Euler: the position with the OLD velocity
    v += params.gravity * dt;
}

// The state-less particle: the same n steps in closed form (the sum of the steps above).
vec3 pl_stateless_position(vec3 x0, vec3 v0, uint n, float dt) {
    float fn = float(n);
    return x0 + v0 * (fn * dt) + params.gravity * (dt * dt * fn * (fn + 1.0) * 0.5);
}
#endif
