#version 450
// Baked once: the surface textures of a tiled teapot, 8 x 8 tiles over the uv square.
//   diffuse_map: terracotta tiles of varying shade, grey grout            (r_d, colour)
//   gloss_map:   r = r_s: glazed tiles 0.75..1.0 with a smudge, matte grout 0.05
//   id_map:      r = (material index + 0.5) / 4, a per-tile material for the dependent lookup
#include "common/hash.glsl"
#include "common/noise.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 diffuse_map;
layout(location = 1) out vec4 gloss_map;
layout(location = 2) out vec4 id_map;
const float kTiles = 8.0;
const float kGrout = 0.07;        // grout width, in tiles
void main() {
    vec2 g = uv * kTiles, cell = floor(g), f = g - cell;
    bool grout = any(lessThan(f, vec2(0.5 * kGrout))) || any(greaterThan(f, vec2(1.0 - 0.5 * kGrout)));
    float shade = hash_pcg(vec3(cell, 1.0));
    float smudge = value_noise(vec3(uv * 24.0, 0.5));
    vec3 tile = mix(vec3(0.30, 0.09, 0.04), vec3(0.50, 0.22, 0.10), shade);
    diffuse_map = vec4(grout ? vec3(0.25) : tile, 1.0);
    gloss_map = vec4(vec3(grout ? 0.05 : mix(0.75, 1.0, smudge)), 1.0);
    float id = floor(hash_pcg(vec3(cell, 2.0)) * 4.0);
    id_map = vec4(vec3((grout ? 0.0 : id) + 0.5) / 4.0, 1.0);
}
