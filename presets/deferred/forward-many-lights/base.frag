#version 450
// The base pass: depth for the shading passes' `equal` test, and the ambient term (what the
// additive per-light passes of method = multipass add to).
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in vec4 v_material;
layout(location = 0) out vec4 lit;
void main() { lit = vec4(params.ambient * v_material.rgb, 1.0); }
