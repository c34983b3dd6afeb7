#version 450
// Test pass: RMSE of four in-scatter radiances against the 8x-step reference, over every pixel and
// the RGB channels, in one work group (256 threads, strided partial sums, then a tree in shared
// memory). Each radiance is R P_R(mu) + M P_M(mu) from its split images (phase_composite.frag's
// formula). errors.e = (plain, plain blurred, interleaved raw, interleaved blurred,
// plain - interleaved blurred, plain blurred - interleaved blurred): the last two must be > 0.
#include "volumetric/atmosphere.glsl"
#include "volumetric/sky_view.glsl"
layout(local_size_x = 256) in;
uniform sampler2D ref_r;
uniform sampler2D ref_m;
uniform sampler2D plain_r;
uniform sampler2D plain_m;
uniform sampler2D plainb_r;
uniform sampler2D plainb_m;
uniform sampler2D raw_r;
uniform sampler2D raw_m;
uniform sampler2D blur_r;
uniform sampler2D blur_m;
layout(std430) buffer Errors { float e[8]; } errors;
shared vec4 partial[256];
void main() {
    ivec2 size = textureSize(ref_r, 0);
    int n = size.x * size.y;
    vec3 sun = atmo_sun_direction(params.sun_elevation, params.sun_azimuth);
    vec4 s = vec4(0.0);
    for (int i = int(gl_LocalInvocationIndex); i < n; i += 256) {
        ivec2 p = ivec2(i % size.x, i / size.x);
        float mu = dot(sky_camera_direction((vec2(p) + 0.5) / vec2(size)), sun);
        vec2 ph = vec2(atmo_phase_rayleigh(mu), atmo_phase_mie(mu, ATMO_G));
#define L(R, M) (texelFetch(R, p, 0).rgb * ph.x + texelFetch(M, p, 0).rgb * ph.y)
        vec3 r = L(ref_r, ref_m);
        vec3 a = L(plain_r, plain_m) - r, b = L(plainb_r, plainb_m) - r;
        vec3 c = L(raw_r, raw_m) - r, d = L(blur_r, blur_m) - r;
        s += vec4(dot(a, a), dot(b, b), dot(c, c), dot(d, d));
    }
    partial[gl_LocalInvocationIndex] = s;
    barrier();
    for (uint k = 128u; k > 0u; k >>= 1u) {
        if (gl_LocalInvocationIndex < k) partial[gl_LocalInvocationIndex] += partial[gl_LocalInvocationIndex + k];
        barrier();
    }
    if (gl_LocalInvocationIndex == 0u) {
        vec4 rmse = sqrt(partial[0] / float(3 * n));
        errors.e[0] = rmse.x;
        errors.e[1] = rmse.y;
        errors.e[2] = rmse.z;
        errors.e[3] = rmse.w;
        errors.e[4] = rmse.x - rmse.w;
        errors.e[5] = rmse.y - rmse.w;
        errors.e[6] = 0.0;
        errors.e[7] = 0.0;
    }
}
