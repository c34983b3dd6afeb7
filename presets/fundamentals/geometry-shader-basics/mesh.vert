#version 450
// World-space positions for the shrinking geometry shader, which projects after shrinking.
layout(location = 0) in vec3 position;
layout(location = 0) out vec3 v_world;
void main() {
    v_world = position;
    gl_Position = vec4(position, 1.0);
    if (!(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
