#version 450
// Stage 3 of 002 (L871-895): the 17-tap linear-lookup Gaussian of passes/post/gauss17.glsl,
// x with BLUR_X, else y; with params.blur off the image passes through.
#include "post/gauss17.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 blur_out;
uniform sampler2D blur_in;

#ifdef BLUR_X
const vec2 kDir = vec2(1.0, 0.0);
#else
const vec2 kDir = vec2(0.0, 1.0);
#endif

void main() {
    blur_out = params.blur ? gauss17_linear(blur_in, uv, kDir / vec2(textureSize(blur_in, 0)), false)
                           : texelFetch(blur_in, ivec2(gl_FragCoord.xy), 0);
}
