#version 450
// Test analysis: every geometry pixel into one of 8 bins of n.l (clamped to [0, 1]; the unlit
// side falls in bin 0), counting pixels, inked pixels and the sum of the darkness 1 - tone
// (fixed point, kUnit per 1) per bin with atomics.
#include "light.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D normal;
uniform sampler2D ink;
layout(std430) buffer bins { uint counts[24]; };  // [0, 8): pixels, [8, 16): inked, [16, 24): darkness sums
const float kUnit = 4096.0;
void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, ivec2(frame.resolution.xy)))) return;
    vec4 nw = texelFetch(normal, px, 0);
    if (nw.w == 0.0) return;
    vec3 l = light_direction();
    float ndl = clamp(dot(normalize(nw.xyz), l), 0.0, 1.0);
    int b = min(int(ndl * 8.0), 7);
    atomicAdd(counts[b], 1u);
    if (texelFetch(ink, px, 0).r > 0.5) atomicAdd(counts[8 + b], 1u);
    float tone = params.ambient + (1.0 - params.ambient) * ndl;
    atomicAdd(counts[16 + b], uint(round((1.0 - tone) * kUnit)));
}
