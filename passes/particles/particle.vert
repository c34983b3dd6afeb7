#version 450
// Each instance is one alive particle (state-full: its slot from the alive list the GPU
// compacted) or one emission id of the last `life` steps (state-less: its position in closed
// form), drawn as a screen-aligned billboard (billboard.glsl, L3689-3731).
#define PL_PARTICLE_ACCESS readonly
#include "particles/particle.glsl"
#include "particles/billboard.glsl"
layout(location = 0) out vec2 corner;
layout(location = 1) out float age01;
void main() {
    vec3 x;
    uint age;
    if (params.mode == MODE_STATELESS) {
        // Steps done after this frame: substeps per frame from the first frame on. The birth step
        // b of instance j: the `life` newest steps hold rate particles each; b < 0 is not born yet.
        // (prewarm: `life` steps before the first frame, as the state-full reset places them).
        int s = (params.prewarm ? params.life : 0) + (frame.index + 1) * params.substeps - 1;   // the last step's index
        int b = s - params.life + 1 + gl_InstanceIndex / params.rate;
        uint e = uint(max(b, 0) * params.rate + gl_InstanceIndex % params.rate);
        vec3 x0, v0;
        pl_birth(e, x0, v0);
        age = uint(s - b);
        x = pl_stateless_position(x0, v0, age, params.dt);
        if (b < 0) { gl_Position = vec4(0, 0, 2, 1); return; }   // outside the clip volume
    } else {
        PlParticle q = particles.p[alive_list.slot[gl_InstanceIndex]];
        x = q.x;
        age = q.age;
    }
    corner = pl_quad_corner(gl_VertexIndex);
    age01 = float(age) / float(params.life);
    gl_Position = frame.view_proj * vec4(pl_billboard_screen(x, corner, params.size, frame.inv_view), 1.0);
}
