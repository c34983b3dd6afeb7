#version 450
// Face pl_iteration of a cube map (repeat = 6, layer = "iteration") from the procedural sky, or,
// for the options the preset's `env` param declares: ENV_SMOOTH, the smooth direction-coloured
// field of smooth_env.glsl (seam and resampling tests); ENV_WHITE, radiance 1 everywhere
// (constant-environment tests). Needs params env and sun_dir.
#include "envmap/cube.glsl"
#include "envmap/sky.glsl"
#include "envmap/smooth_env.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 env;
// SUPERSAMPLE = n (a define, default 1): the sky averaged over n x n directions inside the
// texel, a box prefilter. The sky's ground grid has sharp lines; sampled once per texel they
// alias into dotted lines towards the horizon, where the lines get thinner than a texel.
#ifndef SUPERSAMPLE
#define SUPERSAMPLE 1
#endif
vec3 sky_texel(vec2 uv) {
    vec2 texel = frame.target.zw;   // 1 / the face size
    vec3 c = vec3(0.0);
    for (int i = 0; i < SUPERSAMPLE; ++i)
        for (int j = 0; j < SUPERSAMPLE; ++j) {
            vec2 o = (vec2(i, j) + 0.5) / float(SUPERSAMPLE) - 0.5;
            c += sky_radiance(cube_face_direction(pl_iteration, uv + o * texel), params.sun_dir, 1.0);
        }
    return c / float(SUPERSAMPLE * SUPERSAMPLE);
}
void main() {
    vec3 d = cube_face_direction(pl_iteration, uv);
    vec3 c = SUPERSAMPLE == 1 ? sky_radiance(d, params.sun_dir, 1.0) : sky_texel(uv);
#ifdef ENV_SMOOTH
    if (params.env == ENV_SMOOTH) c = smooth_environment(d);
#endif
#ifdef ENV_WHITE
    if (params.env == ENV_WHITE) c = vec3(1.0);
#endif
    env = vec4(c, 1.0);
}
