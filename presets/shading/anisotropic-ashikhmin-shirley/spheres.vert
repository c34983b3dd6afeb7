#version 450
// Two spheres (instances): 0 at x = -0.6 isotropic (e_u = e_v = n_u), 1 at x = +0.6 with
// e_u = n_u along the tangent and e_v = n_v along the bitangent. The sphere generator's
// tangent follows its u coordinate, round the y axis: "brushed" along the parallels.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 3) in vec4 tangent;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) out vec4 v_tangent;
layout(location = 3) flat out int v_instance;
const float kOffsetX = 0.6;
void main() {
    v_instance = gl_InstanceIndex;
    vec3 p = position + vec3(gl_InstanceIndex == 0 ? -kOffsetX : kOffsetX, 0.0, 0.0);
    v_world = p;
    v_normal = normal;
    v_tangent = tangent;
    gl_Position = frame.view_proj * vec4(p, 1.0);
}
