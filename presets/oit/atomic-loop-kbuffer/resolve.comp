#version 450
// Atomic loop k-buffer, resolve ("The list is simply already sorted", 002_644d46bdce7e5305.txt
// L1613): the slots are ascending, so composite back to front, the farthest held slot first,
// over the opaque colour with the tail already blended in (oit_over, composite.glsl). An empty
// slot (0xffffffff) ends the list.
#include "oit/composite.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(std430) readonly buffer KDepth { uint slot[]; } kdepth;
layout(std430) readonly buffer KColor { uint rgba[]; } kcolor;
layout(rgba16f) uniform writeonly image2D resolved;
uniform sampler2D color;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(resolved);
    if (any(greaterThanEqual(p, size))) return;
    int base = (p.y * size.x + p.x) * params.k;
    int n = 0;
    while (n < params.k && kdepth.slot[base + n] != 0xffffffffu) ++n;
    vec3 c = texelFetch(color, p, 0).rgb;
    for (int i = n - 1; i >= 0; --i) c = oit_over(c, unpackUnorm4x8(kcolor.rgba[base + i]));
    imageStore(resolved, p, vec4(c, 1.0));
}
