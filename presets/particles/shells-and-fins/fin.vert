#version 450
// Positions and normals in object space (= world: the mesh is not moved) for the fin geometry
// shader, which needs the triangle and its three neighbours.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) out vec2 v_uv;
void main() {
    v_world = position;
    v_normal = normal;
    v_uv = uv;
    gl_Position = frame.view_proj * vec4(position, 1.0);
}
