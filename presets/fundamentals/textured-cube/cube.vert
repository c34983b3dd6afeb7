#version 450
// Object -> world (a spin around y driven by the frame clock) -> clip with the frame block's
// view_proj. Normals are rotated by the same matrix (a rotation, so no inverse transpose needed).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;

layout(location = 0) out vec3 v_normal;
layout(location = 1) out vec2 v_uv;

void main() {
    float a = frame.time * params.spin;
    mat3 spin = mat3(cos(a), 0.0, -sin(a), 0.0, 1.0, 0.0, sin(a), 0.0, cos(a));
    vec3 world = spin * position;
    v_normal = spin * normal;
    v_uv = uv;
    gl_Position = frame.view_proj * vec4(world, 1.0);
}
