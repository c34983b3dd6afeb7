#version 450
#include "lighting.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
void main() {
    v_world = position * (kBall.w / 0.5) + kBall.xyz;   // unit-diameter sphere mesh
    v_normal = normal;
    gl_Position = frame.view_proj * vec4(v_world, 1.0);
}
