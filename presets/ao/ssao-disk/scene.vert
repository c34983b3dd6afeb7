#version 450
// KIND 0: the room (floor, instance 0, and back wall, instance 1); 1: the teapot; 2: two
// balls; 3: the test plane facing +z through the origin (scenes "plane" and "probe"). Each
// draw is hidden (every vertex outside the clip volume) unless its scene is selected.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_view_pos;
layout(location = 1) out vec3 v_view_normal;

void main() {
    vec3 p = position, n = normal;
    bool visible = params.scene == SCENE_OBJECTS;
#if KIND == 0
    if (gl_InstanceIndex == 1) p = vec3(position.x, -position.z + 2.5, -2.5), n = vec3(0, 0, 1);
#elif KIND == 1
    p = position + vec3(-0.6, 0.483, 0.1);  // the generator centres its box: lift the bottom (0.483) onto the floor
#elif KIND == 2
    p = position + vec3(0.8 + 0.45 * float(gl_InstanceIndex), 0.4, -0.3 + 0.8 * float(gl_InstanceIndex));
#else
    visible = params.scene != SCENE_OBJECTS;
    p = vec3(position.x, -position.z, 0.0), n = vec3(0, 0, 1);
#endif
    vec4 vp = frame.view * vec4(p, 1.0);
    v_view_pos = vp.xyz;
    v_view_normal = mat3(frame.view) * n;
    gl_Position = frame.proj * vp;
    if (!visible) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
