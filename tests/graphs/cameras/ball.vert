#version 450
// A ball of radius 1 at (3, 0, 0), seen from the cube camera at the origin.
layout(location = 0) in vec3 position;
layout(location = 0) out vec3 world;
void main() {
    world = position + vec3(3.0, 0.0, 0.0);
    gl_Position = frame.view_proj * vec4(world, 1.0);
}
