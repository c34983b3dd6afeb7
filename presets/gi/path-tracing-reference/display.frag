#version 450
// The accumulated radiance to the screen: exposure, then the sRGB target encodes. A pixel the
// interleaved trace has not reached yet since the last reset (alpha 0) shows its tile's first
// pixel, traced on the first frame (interleave.glsl), so a moved camera is never black.
#include "interleave.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D radiance;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 r = texelFetch(radiance, p, 0);
    if (r.a == 0.0) r = texelFetch(radiance, p - p % pt_interleave(), 0);
    color = vec4(r.rgb * params.exposure, 1.0);
}
