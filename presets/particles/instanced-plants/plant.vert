#version 450
// One point per instance: the geometry shader grows the plant from it.
layout(location = 0) flat out int v_instance;
void main() {
    v_instance = gl_InstanceIndex;
    gl_Position = vec4(0.0, 0.0, 0.0, 1.0);
}
