#version 450
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_normal;
void main() {
    v_normal = normal;  // object space = world space (no model transform)
    gl_Position = frame.view_proj * vec4(position, 1.0);
}
