#version 450
// Light assignment: one work group per screen tile, 16 x 16 threads: y = the depth slice,
// x = a lane taking lights x, x + 16, x + 32, ... . The light's sphere in view space against
// the cluster's box (clusters.glsl); on a hit the light is appended to the cluster's list
// through an atomic counter, which hands out the slots: 16 lanes append to the same list at
// once, in no fixed order. cluster_count is cleared to 0 every frame. The lanes are x so that
// neighbouring invocations (one SIMD vector on a CPU driver) append to the *same* list: a plain
// read-increment-write instead of atomicAdd then loses entries even on lavapipe, and the
// assignment test sees it (tried).
#include "deferred/lights.glsl"
#include "clusters.glsl"
layout(local_size_x = 16, local_size_y = 16) in;  // x: light lane, y: slice (kSlices = 16)
layout(std430) buffer cluster_count { uint counts[]; };
layout(std430) writeonly buffer cluster_lights { uint slots[]; };
void main() {
    ivec3 cc = ivec3(gl_WorkGroupID.xy, gl_LocalInvocationID.y);
    int c = cluster_index(cc);
    vec3 lo, hi;
    cluster_box(cc, lo, hi);
    for (int i = int(gl_LocalInvocationID.x); i < params.lights; i += int(gl_WorkGroupSize.x)) {
        PointLight l = point_light(i, frame.time);
        vec3 centre = (frame.view * vec4(l.position, 1.0)).xyz;
        if (!sphere_meets_box(centre, l.radius, lo, hi)) continue;
        uint slot = atomicAdd(counts[c], 1u);
        if (slot < uint(kMaxPerCluster)) slots[uint(c) * uint(kMaxPerCluster) + slot] = uint(i);
    }
}
