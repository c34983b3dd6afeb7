#version 450
// The compute variant of the fBm benchmark: the same field as presets/procedural/fbm's fragment
// pass (fbm.glsl), one invocation per pixel, written with imageStore. 8x8 groups: a square tile
// keeps llvmpipe's SIMD lanes on neighbouring pixels, like the rasterizer's quads do.
#include "../../../presets/procedural/fbm/fbm.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba16f) uniform writeonly image2D field;

void main() {
    ivec2 px = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(px, ivec2(frame.resolution.xy)))) return;
    // The fragment pass's uv: pixel centres, (0,0) = top-left.
    vec2 uv = (vec2(px) + 0.5) * frame.resolution.zw;
    imageStore(field, px, fbm_field(uv));
}
