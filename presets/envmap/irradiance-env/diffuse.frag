#version 450
// The teapot: diffuse image-based lighting (diffuse_ibl.glsl) by the interpolated normal.
#include "diffuse_ibl.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
uniform samplerCube irradiance;
void main() { hdr = vec4(diffuse_ibl(params.albedo, irradiance, normalize(v_normal)), 1.0); }
