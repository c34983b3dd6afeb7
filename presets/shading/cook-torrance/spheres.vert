#version 450
// Three spheres in a row, instance i with RMS slope m = 0.069, 0.24, 0.5 (the document's two
// and a rough one).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out float v_m;
const float kSlopes[3] = float[](0.069, 0.24, 0.5);
void main() {
    vec3 p = position + vec3((float(gl_InstanceIndex) - 1.0) * 1.3, 0.0, 0.0);
    v_world = p;
    v_normal = normal;
    v_m = kSlopes[gl_InstanceIndex];
    gl_Position = frame.view_proj * vec4(p, 1.0);
}
