#version 450
// Min and max of the positive floats of `values` by integer atomics: for non-negative IEEE
// floats the order of their bits as uints is their order as numbers. word 0 = ~min (atomicMax of
// the complement, so a buffer cleared to 0 starts empty), word 1 = max; words 2, 3 the same over
// the masked pixels.
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D values;
uniform sampler2D mask;
layout(std430) buffer Range { uint w[4]; } range;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, textureSize(values, 0)))) return;
    uint bits = floatBitsToUint(texelFetch(values, p, 0).r);
    atomicMax(range.w[0], ~bits);
    atomicMax(range.w[1], bits);
    if (texelFetch(mask, p, 0).a != 0.0) {
        atomicMax(range.w[2], ~bits);
        atomicMax(range.w[3], bits);
    }
}
