#version 450
// composite.frag for split in-scatter: the phase functions applied per pixel after the blur,
//     L_in = R P_R(mu) + M P_M(mu),  mu = dot(view direction, sun)   (002 L2331, L2453-2456)
// then L = L_surface T + L_in, and the tone-mapped colour.
#include "volumetric/atmosphere.glsl"
#include "volumetric/sky_view.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 display;
uniform sampler2D surface;
uniform sampler2D in_rayleigh;
uniform sampler2D in_mie;
uniform sampler2D transmit;
void main() {
    float mu = dot(sky_camera_direction(uv), atmo_sun_direction(params.sun_elevation, params.sun_azimuth));
    vec3 s = texelFetch(surface, ivec2(gl_FragCoord.xy), 0).rgb;
    vec3 l_in = texture(in_rayleigh, uv).rgb * atmo_phase_rayleigh(mu) + texture(in_mie, uv).rgb * atmo_phase_mie(mu, ATMO_G);
    color = vec4(s * texture(transmit, uv).rgb + l_in, 1.0);
    display = vec4(1.0 - exp(-params.exposure * color.rgb), 1.0);
}
