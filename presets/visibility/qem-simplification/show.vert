#version 450
// One mesh of the comparison, moved by OFFSET_X along x (the full mesh on the left, its QEM
// simplification on the right) and, for the floor planes, down to FLOOR_Y. delta.comp places the
// meshes by the same place() so its plane equations are those of the rendered faces.
#include "qem.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_normal;
layout(location = 1) out vec3 v_world;
void main() {
    vec3 p = place(position, FLOOR != 0) + vec3(OFFSET_X, 0.0, 0.0);
    v_normal = normal;
    v_world = p;
    gl_Position = frame.view_proj * vec4(p, 1.0);
}
