#version 450
// Checks of the paraboloid coordinates on 4096 random directions, uniform over the sphere, each
// in the map of its hemisphere (+z map for r_z >= 0, the document's 1 - r_z map otherwise):
//   .r = | dp_direction(dp_coord(r)) - r |    (round trip)
//   .g = | (s, t) |                           (<= 1: each map covers its hemisphere)
#include "envmap/dual_paraboloid.glsl"
#include "common/hash.glsl"
layout(location = 0) out vec2 formula;
void main() {
    vec3 h = hash_pcg3(vec3(gl_FragCoord.xy, 5.0));
    float z = 2.0 * h.x - 1.0, phi = 6.2831853 * h.y, s = sqrt(max(1.0 - z * z, 0.0));
    vec3 r = vec3(s * cos(phi), s * sin(phi), z);
    int layer = r.z >= 0.0 ? 0 : 1;
    vec2 st = dp_coord(r, layer);
    formula = vec2(length(dp_direction(st, layer) - r), length(st));
}
