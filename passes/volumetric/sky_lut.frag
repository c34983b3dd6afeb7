#version 450
// Bakes the sky-view LUT: the atmosphere library's march for the direction of every texel
// (sky_view.glsl), from SKY_ORIGIN. A baked pass: it reruns only when a param changes, so the
// live view pays one fetch per pixel (sky.frag without SKY_DIRECT).
#include "volumetric/atmosphere.glsl"
#include "volumetric/sky_view.glsl"
#ifndef SKY_ORIGIN
#define SKY_ORIGIN frame.camera_pos.xyz
#endif
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
void main() {
    vec3 sun = atmo_sun_direction(params.sun_elevation, params.sun_azimuth);
    AtmoResult a = atmo_scatter(SKY_ORIGIN, sky_lut_direction(uv), sun, 1e30, 0.0, params.steps, params.sub_steps);
    color = vec4(a.radiance, 1.0);
}
