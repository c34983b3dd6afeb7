#version 450
// An independent oracle for level k = pl_iteration: every level-0 texel t lies under level-k
// texel c = min(t >> k, size_k - 1) (floor halving: the last texel of a side also covers the odd
// rows the halving dropped). The maximum over each footprint is built directly from level 0 by
// atomics, not level by level: positive floats order like their bit patterns.
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D base;                  // level 0 alone
uniform sampler2D lvl;                   // level k alone: only its size is used here
layout(r32ui) uniform uimage2D oracle;   // layer k of the oracle array (bind view)
void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(t, textureSize(base, 0)))) return;
    ivec2 c = min(t >> pl_iteration, textureSize(lvl, 0) - 1);
    imageAtomicMax(oracle, c, floatBitsToUint(texelFetch(base, t, 0).r));
}
