#version 450
// A caster flattened onto the receiver plane y = 0 (000_c9f7e5de708ecbb3.txt L4489-4491: "the
// ModelView matrix transforms object into plane; object is drawn flat"): world = model * v, then
// the projection matrix M of planar_shadow.glsl, then the view. The homogeneous result M v is
// passed to the view as it is (the divide by w happens after clipping, like any projection).
//
// Test output: each vertex writes n.p + d of its projected point (p = (M v).xyz / (M v).w) and
// a 1 (written) into `residual`, at element RESIDUAL_BASE + gl_VertexIndex.
#include "shadows/scene.glsl"
#include "shadows/light_homogeneous.glsl"
#include "planar_shadow.glsl"
layout(location = 0) in vec3 position;
layout(std430) buffer residual { vec2 planar_residual[]; };

const vec4 kReceiver = vec4(0.0, 1.0, 0.0, 0.0);   // (n, d): the ground, y = 0

void main() {
    vec4 world = shadow_model(OBJECT) * vec4(position, 1.0);
    vec4 flat_point = planar_shadow_matrix(kReceiver, shadow_light_homogeneous()) * world;
    vec3 p = flat_point.xyz / flat_point.w;
    planar_residual[RESIDUAL_BASE + gl_VertexIndex] = vec2(dot(kReceiver.xyz, p) + kReceiver.w, 1.0);
    gl_Position = frame.view_proj * flat_point;
}
