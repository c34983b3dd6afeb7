#version 450
// KIND 0: the ground plane; 1: pillars, instanced in two rows receding along -z; 2: the test
// wall (the plane turned to face +z, at params.wall_z). VISIBLE hides a draw.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_normal;
layout(location = 1) flat out int v_instance;

void main() {
    vec3 p = position, n = normal;
#if KIND == 1
    int i = gl_InstanceIndex;
    float row = float(i % 2) * 2.0 - 1.0, k = float(i / 2);
    p = position * vec3(0.6, 3.0, 0.6) + vec3(row * 2.5, 1.5, 4.0 - k * 4.0);
#elif KIND == 2
    p = vec3(position.x, -position.z, position.y + params.wall_z);  // plane normal +y -> +z
    n = vec3(0.0, 0.0, 1.0);
#endif
    v_normal = n;
    v_instance = gl_InstanceIndex;
    gl_Position = frame.view_proj * vec4(p, 1.0);
    if (!(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
