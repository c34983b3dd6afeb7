#version 450
// Two boxes side by side; instance 0 shows the colour texture, instance 1 the normals.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 0) out vec2 v_uv;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out int v_which;
void main() {
    float side = gl_InstanceIndex == 0 ? -0.75 : 0.75;
    v_uv = uv;
    v_normal = normal;
    v_which = gl_InstanceIndex;
    gl_Position = frame.view_proj * vec4(position * 1.2 + vec3(side, 0.0, 0.0), 1.0);
}
