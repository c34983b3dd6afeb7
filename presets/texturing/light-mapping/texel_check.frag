#version 450
// At every light-map texel centre: |lightmap x albedo - per-pixel Lambert x albedo| (rgb) with
// the floor's own function (floor.glsl) and the same albedo texel for both, so what is
// compared is the baked light against the light computed where that texel sits.
layout(location = 0) out vec4 diff;
uniform sampler2D albedo;
uniform sampler2D lightmap;
uniform sampler2D premult;
#include "floor.glsl"
void main() {
    vec2 uv = gl_FragCoord.xy / vec2(params.lm_res);
    vec3 a = textureLod(albedo, uv * params.tiles, 0.0).rgb;
    diff = vec4(abs(floor_color(MODE_LIGHTMAP, uv, a) - floor_color(MODE_PER_PIXEL, uv, a)), 1.0);
}
