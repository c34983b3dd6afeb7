#version 450
// Compute variant of blur.frag: one invocation per pixel, reads with the same sampler (clamp,
// linear) at texel centres, writes the storage image.
#include "post/gauss.glsl"

layout(local_size_x = 16, local_size_y = 16) in;
uniform sampler2D blur_in;
layout(rgba16f) uniform writeonly image2D blur_out;

#ifdef BLUR_X
const vec2 kDir = vec2(1.0, 0.0);
#else
const vec2 kDir = vec2(0.0, 1.0);
#endif

void main() {
    ivec2 p = ivec2(gl_GlobalInvocationID.xy);
    ivec2 size = imageSize(blur_out);
    if (any(greaterThanEqual(p, size))) return;  // the last group may overhang the image
    vec2 uv = (vec2(p) + 0.5) / vec2(size);
    vec2 texel = kDir / vec2(textureSize(blur_in, 0));
    vec4 c = params.kernel == KERNEL_LINEAR ? gauss5_linear(blur_in, uv, texel)
                                            : gauss5_discrete(blur_in, uv, texel);
    imageStore(blur_out, p, c);
}
