#version 450
// The scene mesh (scene.obj: precomputed-ao's patches), drawn from the view camera.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 2) in vec2 uv;  // uv.x = patch id (make_scene.py)
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) flat out float v_id;

void main() {
    v_world = position;
    v_normal = normal;
    v_id = uv.x;
    gl_Position = frame.view_proj * vec4(position, 1.0);
}
