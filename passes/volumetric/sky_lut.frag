#version 450
// Bakes the sky-view LUT: the atmosphere library's march for the direction of every texel
// (sky_view.glsl), from SKY_ORIGIN. A baked pass: it reruns only when a param changes, so the
// live view pays one fetch per pixel (sky.frag without SKY_DIRECT).
#include "volumetric/atmosphere.glsl"
#include "volumetric/sky_view.glsl"
#include "volumetric/sky_lut_pass.glsl"
