#version 450
// Per pixel (000 L2366-2381, 001_fe43b953f362fae7.txt L400-410): the interpolated normal is
// renormalised and the same Blinn-Phong evaluated for every fragment. Alpha marks coverage.
#include "lighting.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec3 v_color;
layout(location = 0) out vec4 color;
void main() {
    vec3 n = normalize(v_normal);
    color = vec4(params.mode == MODE_PER_VERTEX ? v_color : blinn_phong(n, v_world), n.z);
}
