#version 450
// volumetric/sky.frag with clouds: the atmosphere library with its ATMO_CLOUDS hook, this
// preset's cloud density (clouds.glsl), then the shared pass body.
#define ATMO_CLOUDS 1
#include "volumetric/atmosphere.glsl"
#include "volumetric/sky_view.glsl"
#include "clouds.glsl"
#include "volumetric/sky_pass.glsl"
