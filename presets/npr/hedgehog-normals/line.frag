#version 450
// The hedgehog's lines, unlit, coloured by direction. For the test, each line fragment also
// widens the box of pixels covered by lines (atomics): bounds = (max x, max y, max (w-1-x),
// max (h-1-y)), and bounds[4] the farthest reach along the screen diagonal (right and up) from
// the view's centre, in 1/16 pixel + kBias (all cleared to 0 per frame). Only with MEASURE
// (params.measure, set by the tests): the contended atomics cost ~2/3 of the live frame on
// lavapipe, and the live view does not read the box.
#ifndef MEASURE
#define MEASURE false
#endif
layout(location = 0) in vec3 g_color;
layout(location = 0) out vec4 color;
layout(std430) buffer line_bounds { uint bounds[5]; };
const float kBias = 65536.0;
void main() {
    if (MEASURE) {
    uvec2 p = uvec2(gl_FragCoord.xy), last = uvec2(frame.resolution.xy) - 1u;
    atomicMax(bounds[0], p.x);
    atomicMax(bounds[1], p.y);
    atomicMax(bounds[2], last.x - p.x);
    atomicMax(bounds[3], last.y - p.y);
    vec2 c = gl_FragCoord.xy - 0.5 * frame.resolution.xy;
    atomicMax(bounds[4], uint(round((c.x - c.y) * 16.0 + kBias)));  // window y grows downwards
    }
    color = vec4(g_color, 1.0);
}
