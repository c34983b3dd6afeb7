#version 450
// Cull(node) of 000_c9f7e5de708ecbb3.txt L6088-6100, one tree level per iteration
// (pl_iteration = L, top down): a node is tested only when its parent intersected the frustum
// (the recursion's "else for all children C: Cull(C)"); a leaf that intersects is drawn —
// appended to the visible list, the indirect draw's instances. The GPU counts the node tests.
layout(local_size_x = 64) in;
#include "field.glsl"
#include "visibility/frustum.glsl"
layout(std430) buffer NodeFlags { uint open[]; } nodes;   // 1 = intersects (cleared each frame)
layout(std430) buffer Visible { uint id[]; } visible;
layout(std430) buffer DrawArgs { uint vertex_count; uint instance_count; uint first_vertex; uint first_instance; } draw_args;
layout(std430) buffer CullStats { uint tests; uint tests_per_level[8]; } stats;
void main() {
    int level = pl_iteration;
    int side = 1 << level;
    int n = int(gl_GlobalInvocationID.x);
    if (n == 0 && level == 0) draw_args.vertex_count = 36u;
    if (n >= side * side) return;
    ivec2 xy = ivec2(n % side, n / side);
    if (level > 0 && nodes.open[field_node_index(level - 1, xy >> 1)] == 0u) return;   // parent culled
    vec4 planes[6];
    pl_frustum_planes(frame.view_proj, planes);
    vec3 lo, hi;
    field_node_bounds(level, xy, lo, hi);
    atomicAdd(stats.tests, 1u);
    atomicAdd(stats.tests_per_level[level], 1u);
    if (!pl_box_intersects_frustum(lo, hi, planes)) return;
    nodes.open[field_node_index(level, xy)] = 1u;
    if (level == FIELD_LEVELS - 1) visible.id[atomicAdd(draw_args.instance_count, 1u)] = uint(xy.y * FIELD + xy.x);
}
