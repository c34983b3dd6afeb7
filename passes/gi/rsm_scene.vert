#version 450
// One mesh of the Cornell box (gi/cornell.glsl): MESH 0 = the `plane` instances (walls),
// MESH 1 = the `cube` instances (blocks), placed by gl_InstanceIndex, through the pass's camera
// (the light's for the reflective shadow map and the spot's depth, the view's for the G-buffer).
#include "gi/cornell.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out vec3 v_albedo;
void main() {
    int i = gl_InstanceIndex;
    mat4 m = MESH == 0 ? cornell_wall(i) : cornell_block(i);
    vec4 w = m * vec4(position, 1.0);
    v_world = w.xyz;
    v_normal = transpose(inverse(mat3(m))) * normal;  // the tall block is scaled non-uniformly
    v_albedo = cornell_albedo(MESH, i);
    gl_Position = frame.view_proj * w;
}
