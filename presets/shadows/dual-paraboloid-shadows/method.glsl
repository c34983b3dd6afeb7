// dual-paraboloid-shadows: the visibility shadows/shade.frag multiplies the light by.
//   DP_METHOD 0  the two paraboloid discs (shadows/paraboloid.glsl; 000 L4730-4739)
//   DP_METHOD 1  test-only: the cube of six maps (shadows/omni_cube.glsl), the same light, bias
//                and scene, for the agreement case
#if DP_METHOD == 0
#include "shadows/paraboloid.glsl"
uniform sampler2DArrayShadow dp_maps;
float shadow_visibility(vec3 p, vec3 n, vec3 l) {
    return dp_visibility(dp_maps, params.light_pos, DP_NEAR, DP_FAR, p, n, l, params.bias_constant, params.bias_slope);
}
#else
#include "shadows/omni_cube.glsl"
uniform samplerCubeShadow shadow_cube;
float shadow_visibility(vec3 p, vec3 n, vec3 l) {
    return omni_cube_visibility(shadow_cube, cameras.light[0].proj, params.light_pos, p, n, l, params.bias_constant, params.bias_slope);
}
#endif
