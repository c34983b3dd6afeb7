// The body of sky_lut.frag (after its includes), shared with passes that include more first
// (raymarched-clouds' sky with its cloud density). Needs atmosphere.glsl and sky_view.glsl.
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
