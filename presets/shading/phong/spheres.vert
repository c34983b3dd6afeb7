#version 450
// Two spheres side by side (2 instances): instance 0 at x = -0.6 is shaded with Phong,
// instance 1 at x = +0.6 with Blinn-Phong, under the same light, material and exponent.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out int v_model;  // 0 Phong, 1 Blinn-Phong
const float kOffsetX = 0.6;                 // sphere centres at x = -+0.6 (radius 0.5)
void main() {
    v_model = gl_InstanceIndex;
    vec3 p = position + vec3(gl_InstanceIndex == 0 ? -kOffsetX : kOffsetX, 0.0, 0.0);
    v_world = p;
    v_normal = normal;
    gl_Position = frame.view_proj * vec4(p, 1.0);
}
