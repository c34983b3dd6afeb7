#version 450
// The model, turned by ROTATION (a mat3 expression), in world space for the geometry shader and
// in clip space for plain drawing. VISIBLE hides it (all vertices outside the clip volume).
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;

mat3 rot_x(float a) { return mat3(1, 0, 0, 0, cos(a), sin(a), 0, -sin(a), cos(a)); }
#ifndef ROTATION
#define ROTATION mat3(1.0)
#endif

void main() {
    mat3 m = ROTATION;
    v_world = m * position;
    v_normal = m * normal;
    gl_Position = frame.view_proj * vec4(v_world, 1.0);
    if (!(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
