#version 450
// Lambert under a directional light, plus the tessellated triangles' edges where `wire` is on
// (distance to the nearest edge from the barycentrics, fwidth for a one-pixel line).
// PLAIN: the reference draw without tessellation (no geometry shader, no barycentrics).
#include "common/brdf.glsl"
layout(location = 0) in vec3 g_world;
layout(location = 1) in vec3 g_normal;
#ifndef PLAIN
layout(location = 2) in vec3 g_bary;
#endif
layout(location = 0) out vec4 hdr;
void main() {
    vec3 n = normalize(g_normal), l = normalize(vec3(0.5, 0.8, 0.3));
    vec3 c = params.albedo * (0.08 + max(dot(n, l), 0.0));
#ifndef PLAIN
    if (params.wire) {
        vec3 w = g_bary / max(fwidth(g_bary), vec3(1e-6));
        float edge = min(w.x, min(w.y, w.z));
        c = mix(mix(c, vec3(0.1, 0.35, 0.7), 0.6), c, smoothstep(0.0, 1.0, edge));
    }
#endif
    hdr = vec4(c, 1.0);
}
