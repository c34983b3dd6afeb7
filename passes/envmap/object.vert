#version 450
// World position and normal of a mesh drawn at the origin; VISIBLE (an expression) hides it.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
void main() {
    v_world = position;
    v_normal = normal;
    gl_Position = frame.view_proj * vec4(position, 1.0);
    if (!(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
