#version 450
// L = albedo / pi * E (diffuse_ibl.glsl, as the teapot shades) for every irradiance texel, laid out as 6 faces side by side (96 x 16).
layout(location = 0) out float furnace;
uniform samplerCube irradiance;
#include "envmap/cube.glsl"
#include "diffuse_ibl.glsl"
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int face = p.x / 16;
    vec3 N = cube_face_direction(face, (vec2(p.x % 16, p.y) + 0.5) / 16.0);
    furnace = diffuse_ibl(params.albedo, irradiance, N).r;
}
