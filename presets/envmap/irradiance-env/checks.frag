#version 450
// L = albedo / pi * E for every irradiance texel, laid out as 6 faces side by side (96 x 16).
layout(location = 0) out float furnace;
uniform samplerCube irradiance;
#include "envmap/cube.glsl"
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    int face = p.x / 16;
    vec3 N = cube_face_direction(face, (vec2(p.x % 16, p.y) + 0.5) / 16.0);
    furnace = params.albedo.r / 3.14159265 * textureLod(irradiance, N, 0.0).r;
}
