#version 450
// Every rasterised triangle faces the eye or faces away: with back faces culled and with front
// faces culled the two counts add up to the count with no culling, triangle for triangle.
// diff = none - (back + front); mismatched = triangles whose flags disagree with that partition.
layout(local_size_x = 64) in;
layout(std430) readonly buffer RasterNone { uint count; uint seen[]; } none;
layout(std430) readonly buffer RasterBack { uint count; uint seen[]; } back;
layout(std430) readonly buffer RasterFront { uint count; uint seen[]; } front;
layout(std430) buffer Split { int diff; uint mismatched; } split;
void main() {
    uint t = gl_GlobalInvocationID.x;
    if (t == 0u) split.diff = int(none.count) - int(back.count) - int(front.count);
    if (t >= uint(TRIANGLES_TOTAL)) return;
    // seen with no culling <=> seen exactly once among the two culled draws
    if (none.seen[t] != back.seen[t] + front.seen[t]) atomicAdd(split.mismatched, 1u);
}
