#version 450
// Box k of the field: instance i draws box visible.id[i] (VISIBLE_LIST) or box i (all of them).
#include "field.glsl"
#if VISIBLE_LIST
layout(std430) readonly buffer Visible { uint id[]; } visible;
#endif
layout(location = 0) out vec3 normal;
layout(location = 1) flat out int object;
void main() {
#if VISIBLE_LIST
    object = int(visible.id[gl_InstanceIndex]);
#else
    object = gl_InstanceIndex;
#endif
    PlBox b = field_box(object);
    vec3 p;
    pl_cube_vertex(gl_VertexIndex, p, normal);
    gl_Position = frame.view_proj * vec4(b.centre + p * b.half_size, 1.0);
}
