#version 450
// Diffuse image-based lighting: L_o = albedo / pi * E(N), one lookup by the normal.
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
uniform samplerCube irradiance;
void main() { hdr = vec4(params.albedo / 3.14159265 * texture(irradiance, normalize(v_normal)).rgb, 1.0); }
