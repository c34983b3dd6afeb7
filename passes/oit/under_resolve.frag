#version 450
// Final composite of the peeling methods: the front-to-back accumulator `front` (premultiplied
// colour, coverage) over what is behind it, `behind` (the opaque colour, or for dual depth peeling
// the back-to-front accumulator that started as the opaque colour). composite.glsl.
#include "oit/composite.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D front;
uniform sampler2D behind;
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    color = vec4(oit_under_resolve(texelFetch(front, p, 0), texelFetch(behind, p, 0).rgb), 1.0);
}
