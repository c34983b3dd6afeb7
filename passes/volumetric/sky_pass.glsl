// The body of sky.frag (after its includes), shared with passes that include more first
// (raymarched-clouds' sky with its cloud density). Needs atmosphere.glsl and sky_view.glsl.
#ifndef SKY_ORIGIN
#define SKY_ORIGIN frame.camera_pos.xyz
#endif
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
#ifdef SKY_DISPLAY
layout(location = 1) out vec4 display;   // tonemap.frag's 1 - exp(-exposure L), saving a pass
#endif
#ifndef SKY_DIRECT
uniform sampler2D sky_lut;
#endif
void sky_main() {
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

void main() {
    sky_main();
#ifdef SKY_DISPLAY
    display = vec4(1.0 - exp(-params.exposure * color.rgb), 1.0);
#endif
}
