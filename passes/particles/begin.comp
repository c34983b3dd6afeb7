#version 450
// Start of a fixed step: the alive list is rebuilt by this step's simulate and emit passes.
layout(local_size_x = 1) in;
#include "particles/particle.glsl"
void main() { counts.alive = 0u; }
