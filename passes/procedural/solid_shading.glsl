// Per-pixel lighting of the solid-texture presets (marble-and-wood, procedural-bump): the
// Phong-style sum of 000_c9f7e5de708ecbb3.txt L980-1020 with Blinn's half vector,
//     c = albedo * (kAmbient + max(n.l, 0)) + specular * (n.h)^shininess * [n.l > 0]
// (the lobe from passes/common/brdf.glsl). All vectors unit, pointing away from the surface.
#ifndef PASSLAB_PROCEDURAL_SOLID_SHADING_GLSL
#define PASSLAB_PROCEDURAL_SOLID_SHADING_GLSL
#include "common/brdf.glsl"

const float kAmbient = 0.15;  // a little light from everywhere, so the shadowed side shows

vec3 solid_shade(vec3 albedo, vec3 n, vec3 l, vec3 v, float specular, float shininess) {
    float n_dot_l = max(dot(n, l), 0.0);
    float spec = n_dot_l > 0.0 ? specular * blinn_phong_lobe(n, normalize(l + v), shininess) : 0.0;
    return albedo * (kAmbient + n_dot_l) + vec3(spec);
}
#endif
