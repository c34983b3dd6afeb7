#version 450
// One mesh placed by the defines OFFSET and SCALE (vec3 each, per pass).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
void main() {
    v_world = position * SCALE + OFFSET;
    v_normal = normal / SCALE;   // inverse transpose of a diagonal scale
    gl_Position = frame.view_proj * vec4(v_world, 1.0);
}
