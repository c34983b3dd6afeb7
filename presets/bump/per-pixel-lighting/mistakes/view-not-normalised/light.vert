#version 450
// Per vertex (Gouraud, 000_c9f7e5de708ecbb3.txt L2366-2381): Blinn-Phong evaluated here and the
// colour interpolated. Per pixel: only the normal and position are passed on.
#include "lighting.glsl"
layout(location = 0) in vec3 position;
layout(location = 1) in vec3 normal;
layout(location = 0) out vec3 v_world;
layout(location = 1) out vec3 v_normal;
layout(location = 2) out vec3 v_color;
void main() {
    v_world = position;
    v_normal = normal;
    v_color = blinn_phong(normalize(normal), position);
    gl_Position = frame.view_proj * vec4(position, 1.0);
}
