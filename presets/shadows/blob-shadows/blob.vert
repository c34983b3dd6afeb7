#version 450
// One blob per instance (gl_InstanceIndex = blob i): a square of side 2 r around the hit point H
// in the receiver plane, lifted by params.lift along its normal ("elevate above hit polygon +
// z-test less or equal", L4474-4476; lift = 0 for the z-test-equal method of L4461-4463).
#include "blob.glsl"
layout(location = 0) out vec2 v_local;   // (-1..1)^2 over the square, the disc is |v_local| <= 1
layout(location = 1) flat out int v_blob;
void main() {
    const vec2 kCorners[6] = vec2[](vec2(-1, -1), vec2(1, -1), vec2(1, 1), vec2(-1, -1), vec2(1, 1), vec2(-1, 1));
    int i = gl_InstanceIndex;
    vec2 q = kCorners[gl_VertexIndex];
    float r = blob_radius(i);
    vec3 p = blob_hit(i) + vec3(q.x * r, LIFT, q.y * r);
    v_local = q;
    v_blob = i;
    gl_Position = frame.view_proj * vec4(p, 1.0);
}
