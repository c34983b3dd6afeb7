#version 450
// The ball is lit per pixel every frame (dynamic objects cannot use the light map).
#include "lighting.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
void main() { hdr = vec4(vec3(0.7) * irradiance(v_world, normalize(v_normal), false), 1.0); }
