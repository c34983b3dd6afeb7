#version 450
// The plane generator's [-1, 1]^2 square stretched to |x| <= half_width, -extent <= z <= 2,
// the same plane that ground.glsl ray-casts for the reference. With FILTER defined (the filter
// passes) the plane is clipped to the columns that show that filter (strips.glsl).
layout(location = 0) in vec3 position;
layout(location = 0) out vec2 v_t;
#ifdef FILTER
#include "strips.glsl"
out float gl_ClipDistance[2];
#endif
void main() {
    vec3 p = vec3(position.x * params.half_width, 0.0, mix(-params.extent, 2.0, 0.5 * position.z + 0.5));
    v_t = vec2(p.x, -p.z) * params.density;
    gl_Position = frame.view_proj * vec4(p, 1.0);
#ifdef FILTER
    // Keep only the columns that show this pass's filter: uv.x = 0.5 x/w + 0.5 in [lo, hi],
    // written as clip distances linear in (x, w) so the clipper cuts the triangles exactly there.
    vec2 cols = filter_columns(FILTER);
    gl_ClipDistance[0] = 0.5 * gl_Position.x + (0.5 - cols.x) * gl_Position.w;
    gl_ClipDistance[1] = (cols.y - 0.5) * gl_Position.w - 0.5 * gl_Position.x;
#endif
}
