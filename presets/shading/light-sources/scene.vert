#version 450
// KIND 0: the floor (y = 0); KIND 1: a ball resting on it at the origin (hidden for scene floor).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
void main() {
    vec3 p = position;
#if KIND == 1
    p += vec3(0.0, 0.6, 0.0);
#endif
    v_world = p;
    v_normal = normal;
    gl_Position = frame.view_proj * vec4(p, 1.0);
#if KIND == 1
    if (params.scene == SCENE_FLOOR) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
#endif
}
