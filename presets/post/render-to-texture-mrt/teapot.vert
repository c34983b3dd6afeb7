#version 450
// The offscreen camera is fixed (its own, not the view's): looking at the teapot from the front.
#include "common/camera.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_normal;
void main() {
    float a = frame.time * params.spin;
    mat3 spin = mat3(cos(a), 0, -sin(a), 0, 1, 0, sin(a), 0, cos(a));
    vec3 p = spin * (position - vec3(0.0, 0.35, 0.0));
    v_normal = spin * normal;
    mat4 proj = perspective(radians(40.0), 1.0, 0.1, 10.0);
    gl_Position = proj * look_at(vec3(0.0, 0.8, 3.0), vec3(0.0), vec3(0.0, 1.0, 0.0)) * vec4(p, 1.0);
}
