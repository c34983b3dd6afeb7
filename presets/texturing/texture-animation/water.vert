#version 450
layout(location = 0) in vec3 position;
layout(location = 2) in vec2 uv;
layout(location = 0) out vec2 v_uv;
void main() {
    v_uv = uv * params.tiles;
    gl_Position = frame.view_proj * vec4(position, 1.0);
}
