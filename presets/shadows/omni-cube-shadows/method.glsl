// omni-cube-shadows: the visibility shadows/shade.frag multiplies the light by, from the cube of
// six depth maps (shadows/omni_cube.glsl; 000_c9f7e5de708ecbb3.txt L4721-4727).
#include "shadows/omni_cube.glsl"
uniform samplerCubeShadow shadow_cube;
float shadow_visibility(vec3 p, vec3 n, vec3 l) {
    return omni_cube_visibility(shadow_cube, cameras.light[0].proj, params.light_pos, p, n, l, params.bias_constant, params.bias_slope);
}
