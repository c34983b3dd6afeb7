#version 450
// The test's reference, written without the triangles or the overlap test: a cell is crossed by
// the plane n . x = d iff its 8 corners are not all on one side, min_k (n . x_k - d) <= 0 <=
// max_k (n . x_k - d) (the plane reaches past the grid, so only the infinite plane matters).
// Then every cell is compared with the voxeliser's: check[0] counts the cells that differ,
// check[1] the cells voxelised, check[2] the cells the plane crosses.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "gi/voxel_scene.glsl"

layout(r32ui) readonly uniform uimage3D voxels;
layout(std430) buffer Check { uint count[3]; } check;

void main() {
    ivec3 c = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(c, ivec3(VX_N)))) return;
    vec4 p = voxel_test_plane();
    float lo = 1e30, hi = -1e30;
    for (int k = 0; k < 8; ++k) {
        vec3 corner = voxel_lo(c + ivec3(k & 1, (k >> 1) & 1, k >> 2));
        float s = dot(p.xyz, corner) - p.w;
        lo = min(lo, s);
        hi = max(hi, s);
    }
    bool crossed = lo <= 0.0 && hi >= 0.0;
    bool marked = imageLoad(voxels, c).r != 0u;
    if (crossed != marked) atomicAdd(check.count[0], 1u);
    if (marked) atomicAdd(check.count[1], 1u);
    if (crossed) atomicAdd(check.count[2], 1u);
}
