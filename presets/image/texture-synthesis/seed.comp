#version 450
// First frame (frame.accum_frame == 0, also after a param change): every texel unknown, but the
// 3x3 seed, copied from the source around kSeedAt. Later frames leave the canvas as it is.
#include "synth_common.glsl"

layout(local_size_x = 8, local_size_y = 8) in;
uniform sampler2D src;
layout(rgba8) uniform writeonly image2D canvas;

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(canvas);
    if (frame.accum_frame > 0 || any(greaterThanEqual(p, size))) return;
    vec4 c = vec4(0.0);
    if (synth_ring(p, size) <= 1)
        c = vec4(texelFetch(src, kSeedAt + p - synth_centre(size), 0).rgb, 1.0 / 255.0);
    imageStore(canvas, p, c);
}
