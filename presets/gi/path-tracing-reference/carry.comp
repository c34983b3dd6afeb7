#version 450
// Copies every pixel's accumulated mean into this frame's copy of the history images (the two
// copies swap every frame), before trace.comp overwrites the pixels it traces this frame: 
// `radiance`, and `l0`, `l1` when params.split. A pixel not yet traced since the accumulation
// reset becomes 0 with alpha 0 (display.frag then interpolates it).
#include "interleave.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f) uniform writeonly image2D radiance;
layout(rgba32f) uniform writeonly image2D l0;
layout(rgba32f) uniform writeonly image2D l1;
uniform sampler2D radiance_prev;
uniform sampler2D l0_prev;
uniform sampler2D l1_prev;
void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    if (any(greaterThanEqual(p, imageSize(radiance)))) return;
    bool reached = uint(max(frame.accum_frame, 0)) > pt_phase(p);
    imageStore(radiance, p, reached ? texelFetch(radiance_prev, p, 0) : vec4(0.0));
    if (!params.split) return;
    imageStore(l0, p, reached ? texelFetch(l0_prev, p, 0) : vec4(0.0));
    imageStore(l1, p, reached ? texelFetch(l1_prev, p, 0) : vec4(0.0));
}
