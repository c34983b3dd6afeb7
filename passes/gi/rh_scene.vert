#version 450
// The GI comparison scene (gi/cornell.glsl) as instanced draws: MESH 0 = the `wall` plane
// (5 instances), 1 = the `block` cube (2). World position and normal out; the pass's camera
// (the view, or the light for the RSM) projects.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out vec3 v_albedo;
#include "gi/cornell.glsl"
void main() {
    mat4 m = MESH == 0 ? cornell_wall(gl_InstanceIndex) : cornell_block(gl_InstanceIndex);
    vec4 w = m * vec4(position, 1.0);
    v_world = w.xyz;
    v_normal = normalize(transpose(inverse(mat3(m))) * normal);  // the blocks scale non-uniformly
    v_albedo = cornell_albedo(MESH, gl_InstanceIndex);
    gl_Position = frame.view_proj * w;
}
