#version 450
// One direction of the 8-lookup Gaussian (passes/post/gauss17.glsl, 002 L871-895).
#include "post/gauss17.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 blurred;
uniform sampler2D blur_in;
#ifdef BLUR_X
const vec2 kDir = vec2(1.0, 0.0);
#else
const vec2 kDir = vec2(0.0, 1.0);
#endif
void main() { blurred = gauss17_linear(blur_in, uv, kDir / vec2(textureSize(blur_in, 0)), params.renormalize); }
