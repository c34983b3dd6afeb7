#version 450
// One thread per object: the marked ones go into the visible list, whose length is the indirect
// draw's instance count (instance k draws object visible.id[k], visibility/box.vert); the others
// are counted as culled, on the GPU.
layout(local_size_x = 64) in;
#include "visibility/scene.glsl"
layout(std430) readonly buffer Marked { uint flag[]; } marked;
layout(std430) buffer Visible { uint id[]; } visible;
layout(std430) buffer DrawArgs { uint vertex_count; uint instance_count; uint first_vertex; uint first_instance; } draw_args;
layout(std430) buffer Stats { uint culled; } stats;
void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i == 0) draw_args.vertex_count = 36u;   // the buffer is cleared to 0 every frame
    if (i >= PL_VIS_OBJECTS) return;
    if (marked.flag[i] == 0u) {
        atomicAdd(stats.culled, 1u);
        return;
    }
    visible.id[atomicAdd(draw_args.instance_count, 1u)] = uint(i);
}
