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
void main() {
    vec3 d = cube_face_direction(pl_iteration, uv);
    vec3 c = sky_radiance(d, params.sun_dir, 1.0);
#ifdef ENV_SMOOTH
    if (params.env == ENV_SMOOTH) c = smooth_environment(d);
#endif
#ifdef ENV_WHITE
    if (params.env == ENV_WHITE) c = vec3(1.0);
#endif
    env = vec4(c, 1.0);
}
