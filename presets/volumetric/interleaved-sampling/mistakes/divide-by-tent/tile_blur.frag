#version 450
// The cross-bilateral blur of interleaved sampling (002_644d46bdce7e5305.txt L2335-2336): the
// in-scatter of a 5 x 5 neighbourhood, weighted
//     w = t(dx) t(dy) exp(-(ln d_i - ln d_c)^2 / (2 sigma^2)),   t = (1/2, 1, 1, 1, 1/2)
// The tent t gives each of the 4 x 4 Bayer offsets the same total weight (taps -2 and +2 share
// one residue mod 4), so a flat region averages all 16 offsets of the tile; the depth term
// (the length the march covered: to the depth buffer's surface, else to the atmosphere's end or
// the ground, which the march stores in transmit.a; ln so it is scale-free; sigma = params.sigma) keeps the sky from bleeding into a
// monolith and back, and the sky near the horizon (rays 100 km to 1000 km long within a degree)
// from mixing across elevations (the "cross" in cross-bilateral: the weights come
// from another image than the one filtered). Normalised by the weights' sum, so a constant field
// stays constant. Two images are blurred with the same weights: the Rayleigh and the Mie
// in-scatter before their phase functions, which are applied per texel after
// the blur (the seed's order, L2331: so the sharp Mie peak around the sun is never blurred); the
// third target is that radiance, at the blur's resolution (the composite upsamples it).
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 color_mie;
layout(location = 2) out vec4 radiance;    // R P_R(mu) + M P_M(mu): the phases applied after the blur
#include "volumetric/atmosphere.glsl"
#include "volumetric/sky_view.glsl"
uniform sampler2D src;
uniform sampler2D src_mie;
uniform sampler2D transmit;   // .a = ln(length marched), written by the march (shafts.frag)

float log_distance(ivec2 p) { return texelFetch(transmit, p, 0).a; }

void blur() {
    ivec2 c = ivec2(gl_FragCoord.xy), size = textureSize(src, 0);
    float lc = log_distance(c);
    const float tent[5] = float[](0.5, 1.0, 1.0, 1.0, 0.5);
    vec3 sum = vec3(0.0), sum_mie = vec3(0.0);
    float wsum = 0.0;
    for (int dy = -2; dy <= 2; dy++) {
        for (int dx = -2; dx <= 2; dx++) {
            ivec2 p = clamp(c + ivec2(dx, dy), ivec2(0), size - 1);
            float dl = log_distance(p) - lc;
            float w = tent[dx + 2] * tent[dy + 2] * exp(-(dl * dl) / (2.0 * params.sigma * params.sigma));
            sum += w * texelFetch(src, p, 0).rgb;
            sum_mie += w * texelFetch(src_mie, p, 0).rgb;
            wsum += w;
        }
    }
    color = vec4(sum / 16.0, 1.0);          // the tent's weights sum to 4 x 4 = 16
    color_mie = vec4(sum_mie / 16.0, 1.0);
}

void main() {
    blur();
    float mu = dot(sky_camera_direction(uv), atmo_sun_direction(params.sun_elevation, params.sun_azimuth));
    radiance = vec4(color.rgb * atmo_phase_rayleigh(mu) + color_mie.rgb * atmo_phase_mie(mu, ATMO_G), 1.0);
}
