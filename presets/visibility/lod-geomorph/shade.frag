#version 450
// Lit teapot; the LOD must not be visible unless params.tint shows it. Counts rasterised triangles
// (visibility/raster_count.glsl) per (level, instance, primitive).
#include "visibility/raster_count.glsl"
layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec2 v_uv;
layout(location = 2) in float v_depth;
layout(location = 3) flat in uint v_triangle_base;
layout(location = 4) in vec3 v_tint;
layout(location = 0) out vec4 color;
void main() {
    pl_count_rasterised(v_triangle_base + uint(gl_PrimitiveID));
    vec3 n = normalize(v_normal) * (gl_FrontFacing ? 1.0 : -1.0);
    float l = 0.25 + 0.75 * max(dot(n, normalize(vec3(0.4, 0.8, 0.5))), 0.0);
    float checker = mod(floor(v_uv.x * 8.0) + floor(v_uv.y * 4.0), 2.0);
    vec3 base = mix(vec3(0.75, 0.55, 0.35), vec3(0.6, 0.4, 0.25), checker);
    if (params.tint) base = mix(base, v_tint, 0.7);
    color = vec4(base * l, 1.0);
}
