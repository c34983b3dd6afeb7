#version 450
// Copies every pixel's accumulated mean into this frame's copy of the history image (the two
// copies swap every frame), before trace.comp overwrites the pixels it traces this frame. A
// pixel not yet traced since the accumulation reset becomes 0 with alpha 0 (display.frag then
// shows its tile's first pixel).
#include "interleave.glsl"
#ifndef OUT
#define OUT radiance
#define OUT_PREV radiance_prev
#endif
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f) uniform writeonly image2D OUT;
uniform sampler2D OUT_PREV;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(OUT)))) return;
    uint n = uint(max(frame.accum_frame, 0));
    imageStore(OUT, p, n > pt_phase(p) ? texelFetch(OUT_PREV, p, 0) : vec4(0.0));
}
