#version 450
// Test-only (enabled = "params.verify"): for every alive particle, after n = age fixed steps
// (t = n dt) since its birth state (x0, v0):
//   residual.euler     = | x - (x0 + v0 t + g t^2/2) - g t dt/2 |   semi-implicit Euler's exact lag
//   residual.stateless = | x - pl_stateless_position(x0, v0, n) |   state-less = state-full
// Both are 0 up to float rounding; dead slots write 0. Explicit Euler (x before v) would lag by
// -g t dt / 2 instead, so the first residual is |g| t dt for it, not 0.
layout(local_size_x = 64) in;
#define PL_PARTICLE_ACCESS readonly
#include "particles/particle.glsl"
layout(std430) writeonly buffer Residual { vec2 r[]; } residual;
void main() {
    uint i = gl_GlobalInvocationID.x;
    if (i >= uint(params.capacity)) return;
    PlParticle q = particles.p[i];
    if (q.alive == 0u) { residual.r[i] = vec2(0); return; }
    float t = float(q.age) * params.dt;
    vec3 parabola = q.x0 + q.v0 * t + 0.5 * params.gravity * t * t;
    vec3 lag = 0.5 * params.gravity * t * params.dt;
    residual.r[i] = vec2(length(q.x - parabola - lag),
                         length(q.x - pl_stateless_position(q.x0, q.v0, q.age, params.dt)));
}
