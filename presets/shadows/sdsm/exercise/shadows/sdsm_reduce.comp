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
            // TODO 1 (002_644d46bdce7e5305.txt L1891-1892: "find tight minimum Z and maximum Z"):
            // skip the background (z == 1). Otherwise d = the view distance -z_view of the pixel:
            // unproject (ndc.xy = pixel centre * 2 - 1, z) with frame.inv_proj, d = -v.z / v.w.
            // Fold d into the tile's not_min / max_bits: for d > 0 the uint bits of floats order
            // as the numbers; the buffer starts at 0, so keep the min as the max of ~bits.
            imageStore(zview, p, vec4(d));
        }
    // TODO 2: publish the tile's result with two global atomics on zbits.w[0] (~bits of the min)
    // and zbits.w[1] (bits of the max), when the tile saw geometry.
}
