#version 450
// One direction of the 17-tap linear-lookup Gaussian of passes/post/gauss17.glsl
// (002_644d46bdce7e5305.txt L871-895, 8 bilinear lookups): x with BLUR_X, else y. Reads
// `blur_in` (bind to rename). Optional defines, each a GLSL bool expression:
//   RENORMALIZE   divide by the printed weights' sum 0.99764 (default false: as printed)
//   BLUR_ENABLED  when false the input passes through unchanged (default true)
// Shared by post/bloom, post/gaussian-17tap-linear and post/lens-flare-screen.
#include "post/gauss17.glsl"
#ifndef RENORMALIZE
#define RENORMALIZE false
#endif
#ifndef BLUR_ENABLED
#define BLUR_ENABLED true
#endif
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 blurred;
uniform sampler2D blur_in;
#ifdef BLUR_X
const vec2 kDir = vec2(1.0, 0.0);
#else
const vec2 kDir = vec2(0.0, 1.0);
#endif
void main() {
    blurred = (BLUR_ENABLED) ? gauss17_linear(blur_in, uv, kDir / vec2(textureSize(blur_in, 0)), RENORMALIZE)
                             : texelFetch(blur_in, ivec2(gl_FragCoord.xy), 0);
}
