#version 450
// Renders the scene at the pass's own resolution, point-sampled at pixel centres: the low-
// resolution colour + guide (1/4 of each side) and, at full resolution, the guide alone (the edge
// buffer, GUIDE_ONLY) and the reference colour (test only, with a guide it does not use).
#include "scene.glsl"

layout(location = 0) in vec2 uv;
#ifdef GUIDE_ONLY
layout(location = 0) out vec4 out_guide;   // r = id, g = depth
#else
layout(location = 0) out vec4 out_color;
layout(location = 1) out vec4 out_guide;
#endif

void main() {
    vec2 at = gl_FragCoord.xy / frame.target.xy;
    float id, depth;
    vec3 c = jbu_scene(at, frame.resolution.x / frame.resolution.y, id, depth);
#ifndef GUIDE_ONLY
    out_color = vec4(c, 1.0);
#endif
    out_guide = vec4(id, depth, 0.0, 1.0);
}
