#version 450
// The floor: two textures with two parametrisations, the tiled surface texture (uv * tiles)
// and the light map (uv), multiplied at run time (floor.glsl).
layout(location = 0) in vec2 v_uv;
layout(location = 0) out vec4 hdr;
uniform sampler2D albedo;
uniform sampler2D lightmap;
uniform sampler2D premult;
#include "floor.glsl"
void main() {
    vec3 a = texture(albedo, v_uv * params.tiles).rgb;   // implicit derivatives: uniform flow
    hdr = vec4(floor_color(params.mode, v_uv, a), 1.0);
}
