#version 450
// Test only: each cluster's list against the brute-force assignment, every light tested
// against the cluster in a plain loop. x = lights wrongly in or out of the list (0 when the
// parallel, atomic build equals the loop), y = the list length. One 4 x 4 block of texels per
// tile holds its 16 slices (slice k at (k % 4, k / 4)).
#include "deferred/lights.glsl"
#include "clusters.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(std430) readonly buffer cluster_count { uint counts[]; };
layout(std430) readonly buffer cluster_lights { uint slots[]; };
layout(rgba32f) uniform writeonly image2D assignment;
void main() {
    ivec2 t = ivec2(gl_GlobalInvocationID.xy);
    ivec3 g = cluster_grid();
    if (any(greaterThanEqual(t, g.xy * 4))) return;
    ivec3 cc = ivec3(t / 4, (t.y % 4) * 4 + t.x % 4);
    int c = cluster_index(cc);
    uint n = counts[c], base = uint(c) * uint(kMaxPerCluster);
    float wrong = n > uint(kMaxPerCluster) ? float(n - uint(kMaxPerCluster)) : 0.0;  // overflow lost lights
    n = min(n, uint(kMaxPerCluster));
    vec3 lo, hi;
    cluster_box(cc, lo, hi);
    uint expected = 0u;
    for (int i = 0; params.verify && i < params.lights; ++i) {
        PointLight l = point_light(i, frame.time);
        bool meets = sphere_meets_box((frame.view * vec4(l.position, 1.0)).xyz, l.radius, lo, hi);
        uint times = 0u;
        for (uint k = 0u; k < n; ++k) times += slots[base + k] == uint(i) ? 1u : 0u;
        wrong += meets ? abs(float(times) - 1.0) : float(times);
        expected += meets ? 1u : 0u;
    }
    imageStore(assignment, t, vec4(wrong, float(n), float(expected), 0.0));
}
