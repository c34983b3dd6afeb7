#version 450
// The sky: the atmosphere library's single-scattering march per pixel (SKY_DIRECT), or one fetch
// of the baked sky-view LUT (sky_lut.frag). SKY_ORIGIN is the eye in metres (default the view
// camera); SKY_PROJECTION 0 = the camera, 1 = the fisheye hemisphere (sky_view.glsl).
// Params read: sun_elevation, sun_azimuth (degrees), steps, sub_steps.
#include "volumetric/atmosphere.glsl"
#include "volumetric/sky_view.glsl"
#ifndef SKY_ORIGIN
#define SKY_ORIGIN frame.camera_pos.xyz
#endif
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
#ifndef SKY_DIRECT
uniform sampler2D sky_lut;
#endif
void main() {
    vec3 d;
    if (params.projection == PROJECTION_FISHEYE) {
        if (!sky_fisheye_direction(uv, frame.target.xy, d)) { color = vec4(0.0, 0.0, 0.0, 1.0); return; }
    } else {
        d = sky_camera_direction(uv);
    }
#ifdef SKY_DIRECT
    vec3 sun = atmo_sun_direction(params.sun_elevation, params.sun_azimuth);
    AtmoResult a = atmo_scatter(SKY_ORIGIN, d, sun, 1e30, 0.0, params.steps, params.sub_steps);
    color = vec4(a.radiance, 1.0);
#else
    color = vec4(texture(sky_lut, sky_lut_uv(d)).rgb, 1.0);
#endif
}
