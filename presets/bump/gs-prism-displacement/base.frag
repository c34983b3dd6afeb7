#version 450
// The undisplaced mesh with the same shading (interpolated normal, no relief): the reference
// the prisms must reproduce when the height field is zero.
#include "surface.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec2 v_uv;
layout(location = 2) in vec3 v_t;
layout(location = 3) in vec3 v_b;
layout(location = 4) in vec3 v_n;
layout(location = 0) out vec4 base;
void main() { base = vec4(surface_color(normalize(v_n), v_uv, 0.0, v_world), 1.0); }   // alpha 1: covered
