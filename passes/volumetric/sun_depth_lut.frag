#version 450
// Bakes the optical depth towards the sun over (height, cos of the sun's zenith angle): the
// library's own 16-sample march (atmo_sun_depth) per texel, stored as (tau_R, tau_M). Rerun only
// when a param changes (bake = true); the live light shafts then fetch instead of marching.
#include "volumetric/atmosphere.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    vec3 p, sun;
    atmo_sun_lut_point(uv, p, sun);
    color = vec4(atmo_sun_depth(p, sun, 16), 0.0, 1.0);
}
