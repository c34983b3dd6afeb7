// A smooth test environment: radiance 0.5 + 0.35 d, so the colour names the direction (red
// towards +x, green +y, blue +z) and changes by at most 0.35 per radian. Seams and flips in a
// map show up as jumps; a correct map differs between neighbouring texels only by that slope.
#ifndef PASSLAB_SMOOTH_ENV_GLSL
#define PASSLAB_SMOOTH_ENV_GLSL
const float kSmoothEnvSlope = 0.35;
vec3 smooth_environment(vec3 d) { return 0.5 + kSmoothEnvSlope * normalize(d); }
#endif
