#version 450
// Pass 1 of two-surface refraction (004_9a40ad89bdfc582a.txt L782-784, L799-803): the back faces
// of the object seen from the eye (cull = "front"), the nearest of them (depth test less):
//   back_normal: world normal of the back face (pointing out of the object, away from the eye)
//   back_depth:  its distance along the view axis, -z_view > 0 (0 where no back face: the clear)
// Depth complexity > 2 (the teapot's spout and handle) leaves one layer only: which one to keep
// is one of the "open challenges" of L813-815; here the nearest.
#include "safe_normal.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 back_normal;
layout(location = 1) out vec4 back_depth;
void main() {
    // Outward: a back face's normal points away from the eye.
    vec3 n = safe_normal(v_normal, v_world);
    back_normal = vec4(faceforward(n, frame.camera_pos.xyz - v_world, n), 1.0);
    back_depth = vec4(-(frame.view * vec4(v_world, 1.0)).z, 0.0, 0.0, 1.0);
}
