#version 450
// Test-only: every box tested on its own (no hierarchy). brute.count = boxes that intersect;
// brute.missing = those the hierarchy did not draw, brute.extra = drawn ones it would not.
layout(local_size_x = 64) in;
#include "field.glsl"
#include "visibility/frustum.glsl"
layout(std430) readonly buffer NodeFlags { uint open[]; } nodes;
layout(std430) buffer Brute { uint count; uint missing; uint extra; } brute;
void main() {
    int i = int(gl_GlobalInvocationID.x);
    if (i >= FIELD * FIELD) return;
    vec4 planes[6];
    pl_frustum_planes(frame.view_proj, planes);
    PlBox b = field_box(i);
    bool in_frustum = pl_box_intersects_frustum(b.centre - b.half_size, b.centre + b.half_size, planes);
    bool drawn = nodes.open[field_node_index(FIELD_LEVELS - 1, ivec2(i % FIELD, i / FIELD))] != 0u;
    if (in_frustum) atomicAdd(brute.count, 1u);
    if (in_frustum && !drawn) atomicAdd(brute.missing, 1u);
    if (!in_frustum && drawn) atomicAdd(brute.extra, 1u);
}
