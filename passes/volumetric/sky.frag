#version 450
// The sky: the atmosphere library's single-scattering march per pixel (SKY_DIRECT), or one fetch
// of the baked sky-view LUT (sky_lut.frag). SKY_ORIGIN is the eye in metres (default the view
// camera); params.projection: the view camera or the fisheye hemisphere (sky_view.glsl).
// SKY_DISPLAY adds a second target with the tone-mapped colour. Params read: sun_elevation,
// sun_azimuth (degrees), steps, sub_steps, projection (and exposure with SKY_DISPLAY).
#include "volumetric/atmosphere.glsl"
#include "volumetric/sky_view.glsl"
#include "volumetric/sky_pass.glsl"
