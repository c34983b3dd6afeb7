#version 450
// One box per instance: the wall (WALL = 1), every object (the unculled reference), or the
// objects a cull pass kept (VISIBLE_LIST = 1: instance k draws object visible.id[k]).
#include "visibility/scene.glsl"
#if VISIBLE_LIST
layout(std430) readonly buffer Visible { uint id[]; } visible;
#endif
layout(location = 0) out vec3 normal;
layout(location = 1) flat out int object;
void main() {
#if WALL
    PlBox b = pl_vis_wall();
    object = -1;
#elif VISIBLE_LIST
    object = int(visible.id[gl_InstanceIndex]);
    PlBox b = pl_vis_object(object);
#else
    object = gl_InstanceIndex;
    PlBox b = pl_vis_object(object);
#endif
    vec3 p;
    pl_cube_vertex(gl_VertexIndex, p, normal);
    gl_Position = frame.view_proj * vec4(b.centre + p * b.half_size, 1.0);
}
