#version 450
// KIND 0: the room (floor, instance 0, and back wall, instance 1) for the objects scene;
// 1: the teapot; 2: three balls; 3: the test geometry — a plane facing +z (scene "plane") or
// two walls at 90 degrees meeting at x = 0 with the corner away from the camera ("crease").
// Each draw is hidden (all vertices outside the clip volume) unless its scene is selected.
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_view_pos;
layout(location = 1) out vec3 v_view_normal;

const float kH = 0.70710678;  // cos 45 = sin 45

void main() {
    vec3 p = position, n = normal;
    bool visible = params.scene == SCENE_OBJECTS;
#if KIND == 0
    if (gl_InstanceIndex == 1) p = vec3(position.x, -position.z + 3.0, -3.0), n = vec3(0, 0, 1);  // back wall
#elif KIND == 1
    p = position + vec3(-0.4, 0.0, 0.2);
#elif KIND == 2
    p = position + vec3(0.9 + 0.55 * float(gl_InstanceIndex), 0.35, -0.6 + 0.5 * float(gl_InstanceIndex));
#else
    visible = params.scene != SCENE_OBJECTS;
    if (params.scene == SCENE_PLANE) {
        if (gl_InstanceIndex == 1) visible = false;
        p = vec3(position.x, -position.z, 0.0), n = vec3(0, 0, 1);
    } else {
        // position.x in [-10, 10] -> t in [0, 20] along the wall from the corner.
        float t = position.x + 10.0, side = gl_InstanceIndex == 0 ? 1.0 : -1.0;
        p = vec3(side * t * kH, -position.z, t * kH);
        n = vec3(-side * kH, 0.0, kH);
    }
#endif
    vec4 vp = frame.view * vec4(p, 1.0);
    v_view_pos = vp.xyz;
    v_view_normal = mat3(frame.view) * n;
    gl_Position = frame.proj * vp;
    if (!visible) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
