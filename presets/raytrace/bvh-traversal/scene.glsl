// bvh-traversal's scene, shared by the trace (BVH and brute force) so that both trace exactly
// the same rays: the teapot standing on a floor, two instances of the scene buffer's meshes
// [teapot, floor] (mesh index = instance index).
#include "raytrace/stages.glsl"
#include "raytrace/pinhole.glsl"

// The teapot generator centres its bounding box: its base is 0.4828 below its origin (host/scene/
// teapot.cpp), so the instance is lifted by that much to stand on the floor at y = 0.
const float TEAPOT_BASE = 0.4828;

int rt_instance_count() { return 2; }
uint rt_instance_mesh(int instance) { return uint(instance); }
mat4 rt_object_from_world(int instance) {
    float lift = instance == 0 ? TEAPOT_BASE : 0.0;
    return mat4(vec4(1, 0, 0, 0), vec4(0, 1, 0, 0), vec4(0, 0, 1, 0), vec4(0, -lift, 0, 1));
}
