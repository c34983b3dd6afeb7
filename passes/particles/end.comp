#version 450
// End of a fixed step: the emitted slots leave the dead stack, the clock advances.
layout(local_size_x = 1) in;
#include "particles/particle.glsl"
void main() {
    uint n = min(uint(params.rate), counts.dead);
    counts.dead -= n;
    counts.emitted += n;
    counts.step += 1u;
}
