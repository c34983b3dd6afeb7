#version 450
// Counts, per level k = pl_iteration, the texels of the pyramid that differ from the oracle
// (and a level whose size is not Vulkan's floor halving of level 0).
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D base;   // level 0 alone
uniform sampler2D lvl;    // level k alone
layout(r32ui) readonly uniform uimage2D oracle;  // layer k
layout(r32ui) uniform uimage2D bad;
void main() {
    ivec2 c = ivec2(gl_GlobalInvocationID.xy);
    ivec2 s = textureSize(lvl, 0);
    if (any(greaterThanEqual(c, s))) return;
    bool size_ok = s == max(textureSize(base, 0) >> pl_iteration, ivec2(1));
    if (texelFetch(lvl, c, 0).r != uintBitsToFloat(imageLoad(oracle, c).r) || !size_ok)
        imageAtomicAdd(bad, ivec2(pl_iteration, 0), 1u);
}
