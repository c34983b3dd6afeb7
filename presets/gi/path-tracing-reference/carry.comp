#version 450
// Resets the accumulation: on the first frame after a reset (frame.accum_frame = 0 after any
// param or camera change) every pixel becomes 0 with alpha 0, in `radiance`, and in `l0`, `l1`
// when params.split; trace.comp then writes this frame's pixels. The images are updated in place
// (trace.comp reads a pixel's mean and writes the new one; no history copy to carry forward), so a
// pixel not yet traced since the reset is still 0 with alpha 0 (display.frag interpolates it),
// and on every later frame this pass only tests and returns. One invocation per 8 x 8 block
// of pixels (threads = ceil_div(view, 8)): llvmpipe pays per work group even when it returns at
// once, and a thread per pixel would be 3600 groups at 640x360 for a pass that mostly does nothing.
layout(local_size_x = 8, local_size_y = 8) in;
layout(rgba32f) uniform writeonly image2D radiance;
layout(rgba32f) uniform writeonly image2D l0;
layout(rgba32f) uniform writeonly image2D l1;
void main() {
    if (frame.accum_frame > 0) return;
    ivec2 size = imageSize(radiance);
    for (int y = 0; y < 8; ++y)
        for (int x = 0; x < 8; ++x) {
            ivec2 p = ivec2(gl_GlobalInvocationID.xy) * 8 + ivec2(x, y);
            if (any(greaterThanEqual(p, size))) continue;
            imageStore(radiance, p, vec4(0.0));
            if (!params.split) continue;
            imageStore(l0, p, vec4(0.0));
            imageStore(l1, p, vec4(0.0));
        }
}
