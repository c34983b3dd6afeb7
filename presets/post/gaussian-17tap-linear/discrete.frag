#version 450
// The reference: the same 1D kernel as 15 unfiltered fetches with the recovered discrete weights.
#include "post/gauss17.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 blurred;
uniform sampler2D blur_in;
#ifdef BLUR_X
const ivec2 kDir = ivec2(1, 0);
#else
const ivec2 kDir = ivec2(0, 1);
#endif
void main() { blurred = gauss17_discrete(blur_in, ivec2(gl_FragCoord.xy), kDir, params.renormalize); }
