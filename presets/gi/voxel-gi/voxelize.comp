#version 450
// Voxelisation in compute: one thread per cell, testing every triangle of every instance (the
// triangle records of the host's `triangles` buffer, placed by gi/cornell.glsl) with the
// separating-axis test; the cell keeps the largest id of the triangles touching it, id = 1 +
// 8 * instance + face, so a cell shared by two surfaces does not depend on the order of anything.
// (The first version ran one thread per triangle over its bounding box with imageAtomicMax; on
// lavapipe its 64^3-iteration loops stopped after ~30k iterations and the tilted-plane test
// caught it: 972 of 7917 cells marked. Per cell the loops are 34 triangles long.)
// params.scene = plane / slab voxelises only the test plane.
layout(local_size_x = 4, local_size_y = 4, local_size_z = 4) in;

#include "gi/voxel_scene.glsl"
#include "raytrace/bvh.glsl"

layout(r32ui) writeonly uniform uimage3D voxels_out;

void main() {
    ivec3 cell = ivec3(gl_GlobalInvocationID);
    if (any(greaterThanEqual(cell, ivec3(VX_N)))) return;
    vec3 h = vec3(0.5 * VX_SIZE), centre = voxel_lo(cell) + h;
    uint best = 0u;
    for (int inst = 0; inst < voxel_instances(); ++inst) {
        PlSceneMesh m = pl_scene_mesh(uint(voxel_instance_mesh(inst)));
        mat4 w = voxel_instance_placement(inst);
        for (uint j = 0u; j < m.triangle_count; ++j) {
            PlSceneTriangle t = pl_scene_triangle(m.triangle_offset + j);
            vec3 a = (w * vec4(t.v0, 1.0)).xyz, b = (w * vec4(t.v1, 1.0)).xyz, c = (w * vec4(t.v2, 1.0)).xyz;
            if (!voxel_triangle_overlaps(a, b, c, centre, h)) continue;
            best = max(best, uint(1 + 8 * inst + voxel_face_of_normal(cross(b - a, c - a))));
        }
    }
    imageStore(voxels_out, cell, uvec4(best));
}
