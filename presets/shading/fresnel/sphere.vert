#version 450
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_normal;
layout(location = 1) out vec3 v_world;
void main() {
    v_normal = normal;
    v_world = position;
    gl_Position = frame.view_proj * vec4(position, 1.0);
}
