#version 450
// The floor: two textures with two parametrisations, the tiled surface texture (uv * tiles)
// and the light map (uv), multiplied at run time (floor.glsl).
// uv_check (tests): |floor_position(uv) - the mesh's own position|, which must be ~0 for the
// light map (baked at floor_position) to land where it was computed.
layout(location = 0) in vec2 v_uv;
layout(location = 1) in vec3 v_world;
layout(location = 0) out vec4 hdr;
layout(location = 1) out vec4 uv_check;
uniform sampler2D albedo;
uniform sampler2D lightmap;
uniform sampler2D premult;
#include "floor.glsl"
void main() {
    vec3 a = texture(albedo, v_uv * params.tiles).rgb;   // implicit derivatives: uniform flow
    hdr = vec4(floor_color(params.mode, v_uv, a), 1.0);
    uv_check = vec4(distance(floor_position(v_uv), v_world), 0.0, 0.0, 1.0);
}
