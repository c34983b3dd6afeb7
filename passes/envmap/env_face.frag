#version 450
// Face pl_iteration of a cube map (repeat = 6, layer = "iteration"): for each texel, the
// direction it stands for and the environment's radiance there — or, with params.env ==
// ENV_FACES, the face's flat test colour (with ENV_WHITE / ENV_POINT options: radiance 1
// everywhere, or one bright texel). Needs params env (sky|faces|...) and sun_dir.
#include "envmap/cube.glsl"
#include "envmap/sky.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 env;
const vec3 kFaceColors[6] = vec3[](vec3(1, 0, 0), vec3(0, 1, 1), vec3(0, 1, 0), vec3(1, 0, 1), vec3(0, 0, 1), vec3(1, 1, 0));
void main() {
    vec3 d = cube_face_direction(pl_iteration, uv);
    env = vec4(params.env == ENV_FACES ? kFaceColors[pl_iteration] : sky_radiance(d, params.sun_dir, 1.0), 1.0);
#ifdef ENV_WHITE
    // The white furnace: radiance 1 in every direction.
    if (params.env == ENV_WHITE) env = vec4(1.0);
#endif
#ifdef ENV_DIRECTIONS
    // The direction each texel stands for, as its colour (a float cube): a lookup along a texel's
    // own direction must return it, which tests the face orientation against the hardware.
    if (params.env == ENV_DIRECTIONS) env = vec4(d, 1.0);
#endif
#ifdef ENV_POINT
    // One bright texel (face +X, texel (3, 4)), black elsewhere: a point-like light.
    if (params.env == ENV_POINT) env = vec4(vec3(pl_iteration == 0 && ivec2(gl_FragCoord.xy) == ivec2(3, 4) ? 100.0 : 0.0), 1.0);
#endif
}
