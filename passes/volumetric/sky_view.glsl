// How the sky presets map a pixel to a view direction, and the sky-view LUT's parameterisation.
#ifndef PASSLAB_VOLUMETRIC_SKY_VIEW_GLSL
#define PASSLAB_VOLUMETRIC_SKY_VIEW_GLSL

// The world-space direction through a fullscreen pass's uv, from the view camera.
vec3 sky_camera_direction(vec2 uv) {
    vec4 w = frame.inv_view_proj * vec4(uv * 2.0 - 1.0, 1.0, 1.0);
    return normalize(w.xyz / w.w - frame.camera_pos.xyz);
}

// Fisheye (equidistant azimuthal) view of the upper hemisphere: the centre of the largest
// centred square is the zenith, its inscribed circle the horizon, up on screen is -z (towards
// azimuth 0). Returns false outside the circle. The tests read the zenith at the image centre.
bool sky_fisheye_direction(vec2 uv, vec2 size, out vec3 d) {
    vec2 q = (uv - 0.5) * size / min(size.x, size.y) * 2.0;   // unit circle = horizon
    float r = length(q);
    if (r > 1.0) { d = vec3(0.0, 1.0, 0.0); return false; }
    float theta = r * 1.5707963;                              // angle from the zenith
    vec2 a = r > 0.0 ? q / r : vec2(0.0);
    d = vec3(sin(theta) * a.x, cos(theta), sin(theta) * a.y);
    return true;
}

// Sky-view LUT (a 2D table of the sky's radiance over directions, baked when a param changes,
// so the live view costs one texture fetch; Hillaire 2020's "sky-view LUT" layout): u =
// azimuth / 2 pi, v from the elevation with a square-root warp that spends half the rows within
// ~22 degrees of the horizon, where the sky changes fastest.
vec2 sky_lut_uv(vec3 d) {
    float elev = asin(clamp(d.y, -1.0, 1.0));
    float az = atan(d.x, -d.z);
    float v = 0.5 + 0.5 * sign(elev) * sqrt(abs(elev) / 1.5707963);
    return vec2(fract(az / 6.2831853 + 1.0), 1.0 - v);
}

vec3 sky_lut_direction(vec2 uv) {
    float s = (1.0 - uv.y) * 2.0 - 1.0;
    float elev = sign(s) * s * s * 1.5707963;
    float az = uv.x * 6.2831853;
    return vec3(cos(elev) * sin(az), sin(elev), -cos(elev) * cos(az));
}
#endif
