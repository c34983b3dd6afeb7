#version 450
layout(location = 0) in vec3 position;
layout(location = 2) in vec2 uv;
layout(location = 0) out vec2 v_uv;
layout(location = 1) out vec3 v_world;
void main() {
    v_uv = uv;
    v_world = position;
    gl_Position = frame.view_proj * vec4(position, 1.0);
}
