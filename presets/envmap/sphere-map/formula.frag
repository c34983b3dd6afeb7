#version 450
// Checks of the sphere-map formula on 4096 random eye-space directions r at angle alpha from
// the eye direction +z (alpha uniform in [0, ALPHA_MAX]):
//   .r = | |uv - 0.5| - sin(alpha / 2) / 2 |      (where the direction lands, docs/catalogue.md)
//   .g = | sphere_map_direction(uv) - r |          (round trip through the inverse)
#include "envmap/sphere_map.glsl"
#include "common/hash.glsl"
layout(location = 0) out vec2 formula;
const float kAlphaMax = 3.1241;  // 179 degrees: at 180 every rim point is r = -z and the inverse is singular
void main() {
    vec3 h = hash_pcg3(vec3(gl_FragCoord.xy, 3.0));
    float alpha = kAlphaMax * h.x, phi = 6.2831853 * h.y;
    vec3 r = vec3(sin(alpha) * cos(phi), sin(alpha) * sin(phi), cos(alpha));
    vec2 uv = sphere_map_coord(r);
    formula = vec2(abs(length(uv - 0.5) - 0.5 * sin(0.5 * alpha)), length(sphere_map_direction(uv) - r));
}
