#version 450
// One sphere at the origin (the same for both passes: each pass renders its model into its
// own image, the display shows them split down the middle).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
void main() {
    v_world = position;
    v_normal = normal;
    gl_Position = frame.view_proj * vec4(position, 1.0);
}
