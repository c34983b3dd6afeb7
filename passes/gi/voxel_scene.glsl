// What presets/gi/voxel-gi voxelises: the Cornell box of gi/cornell.glsl (instances 0..4 walls,
// 5..6 blocks; meshes 0 wall, 1 block of the `tris` buffer), or with params.scene = plane / slab
// only the test plane (mesh 2, a 6 x 6 plane reaching past the grid on every side), tilted or
// axis-aligned.
#ifndef PASSLAB_GI_VOXEL_SCENE_GLSL
#define PASSLAB_GI_VOXEL_SCENE_GLSL

#include "gi/cornell.glsl"
#include "gi/voxel_grid.glsl"

int voxel_instances() { return params.scene == SCENE_CORNELL ? CORNELL_WALLS + CORNELL_BLOCKS : 1; }

int voxel_instance_mesh(int i) {
    if (params.scene != SCENE_CORNELL) return 2;
    return i < CORNELL_WALLS ? 0 : 1;
}

// The test plane: normal (unit) and offset, n . x = d. Tilted: a generic orientation, so no cell
// corner lies on it; slab: y = -0.49, inside cell layer 17 (y in [-0.49805, -0.46484]).
vec4 voxel_test_plane() {
    if (params.scene == SCENE_SLAB) return vec4(0.0, 1.0, 0.0, -0.49);
    return vec4(normalize(vec3(0.31, 0.83, -0.47)), 0.113);
}

mat4 voxel_instance_placement(int i) {
    if (params.scene == SCENE_CORNELL) return i < CORNELL_WALLS ? cornell_wall(i) : cornell_block(i - CORNELL_WALLS);
    // The plane mesh (normal +Y, through the origin) turned onto voxel_test_plane().
    vec4 p = voxel_test_plane();
    vec3 n = p.xyz, t = normalize(cross(n, abs(n.x) < 0.9 ? vec3(1, 0, 0) : vec3(0, 0, 1))), s = cross(n, t);
    return mat4(vec4(t, 0.0), vec4(n, 0.0), vec4(s, 0.0), vec4(n * p.w, 1.0));
}

// 0..5 = +X, -X, +Y, -Y, +Z, -Z: the axis of the largest normal component.
int voxel_face_of_normal(vec3 n) {
    vec3 a = abs(n);
    if (a.x >= a.y && a.x >= a.z) return n.x > 0.0 ? 0 : 1;
    if (a.y >= a.z) return n.y > 0.0 ? 2 : 3;
    return n.z > 0.0 ? 4 : 5;
}

vec3 voxel_face_normal(int f) {
    vec3 a = f < 2 ? vec3(1, 0, 0) : (f < 4 ? vec3(0, 1, 0) : vec3(0, 0, 1));
    return f % 2 == 0 ? a : -a;
}

#endif
