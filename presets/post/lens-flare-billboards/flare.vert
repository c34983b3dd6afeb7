#version 450
// One billboard per instance (vertex_count = 6: two triangles), a square of side 2 r_i around
// p_i (flares.glsl), in pixels, then to Vulkan NDC (y down: pixel (0, 0) is the top-left).
// Invisible flares (light outside the view) collapse to a point: no fragments.
#include "flares.glsl"
layout(location = 0) out vec2 v_local;
layout(location = 1) flat out int v_flare;
void main() {
    const vec2 corners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
    int i = gl_InstanceIndex;
    vec2 res = frame.resolution.xy;
    vec2 q = corners[gl_VertexIndex % 6];
    float r = flare_visibility(params.light) > 0.0 ? flare_radius(i, params.scale, res) : 0.0;
    vec2 px = flare_centre(i, params.light, params.spacing, res) + q * r;
    v_local = q;
    v_flare = i;
    gl_Position = vec4(px / res * 2.0 - 1.0, 0.0, 1.0);
}
