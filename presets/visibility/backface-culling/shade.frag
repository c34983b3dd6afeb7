#version 450
// Lit colour per instance, and the rasterised-triangle count (visibility/raster_count.glsl).
#include "visibility/raster_count.glsl"
layout(location = 0) in vec3 v_normal;
layout(location = 1) flat in uint v_instance;
layout(location = 0) out vec4 color;
void main() {
    pl_count_rasterised(v_instance * uint(TRIANGLES) + uint(gl_PrimitiveID));
    vec3 base = 0.45 + 0.4 * cos(6.2831853 * (vec3(0.0, 0.33, 0.67) + float(v_instance) * 0.21));
    vec3 n = normalize(v_normal) * (gl_FrontFacing ? 1.0 : -1.0);
    float l = 0.3 + 0.7 * max(dot(n, normalize(vec3(0.4, 0.7, 0.6))), 0.0);
    color = vec4(base * l, 1.0);
}
