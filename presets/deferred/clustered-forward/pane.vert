#version 450
// The transparent surface: a glass pane standing on the floor across the scene (the plane
// mesh's x, z turned upright), tinted, with a little specular.
layout(location = 0) in vec3 position;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out vec4 v_material;
const float kWidth = 9.0, kHeight = 2.2, kZ = 1.2;  // metres; z of the pane
void main() {
    vec3 p = vec3(position.x * kWidth, (0.5 - position.z) * kHeight, kZ);
    v_world = p;
    v_normal = vec3(0.0, 0.0, 1.0);
    v_material = vec4(0.6, 0.85, 0.95, 0.5);
    gl_Position = frame.view_proj * vec4(p, 1.0);
#ifdef VISIBLE
    if (!(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
#endif
}
