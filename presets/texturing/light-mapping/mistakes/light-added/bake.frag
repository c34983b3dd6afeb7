#version 450
// EXERCISE — light mapping, the bake (000_c9f7e5de708ecbb3.txt L2157-2162, L2192-2196;
// 003_cfc3b5b225ddab3d.txt L383-401): "map back to worldspace to calculate lighting". This pass
// runs once per light-map texel (gl_FragCoord.xy is the texel's pixel position) and stores the
// view-independent diffuse irradiance of the floor point that texel covers. The run-time half
// is in floor.glsl (TODO 3, 4).
//     passlab run   texturing/light-mapping --exercise presets/texturing/light-mapping/exercise
//     passlab grade texturing/light-mapping --exercise presets/texturing/light-mapping/exercise
// With PREMULTIPLIED the albedo is multiplied in, at the light map's resolution: the
// "premultiply textures by light maps" of L2198-2199, and why it is bad (L2203-2214).
#include "lighting.glsl"
layout(location = 0) out vec4 lightmap;
#ifdef PREMULTIPLIED
uniform sampler2D albedo;
#endif
void main() {
    // TODO 1: the light map coordinate this texel stands for (L2192-2196). The map is
    // params.lm_res texels on a side over uv in [0, 1]; a bilinear lookup at run time returns a
    // texel's value exactly at the texel's CENTRE, (i + 0.5) / N for texel i. What does
    // gl_FragCoord.xy hold for texel i?
    vec2 uv = gl_FragCoord.xy / vec2(params.lm_res);
    // TODO 2: the irradiance there (L2157-2162, L2168): take uv back to its floor point
    // (floor_position, lighting.glsl) and evaluate irradiance(p, n, shadows) with the floor's
    // normal and the ball's shadow:
    //     E(p, n) = sum_k I_k max(n . l_k, 0) / |L_k - p|^2 * V_k(p) + ambient
    vec3 e = irradiance(floor_position(uv), vec3(0.0, 1.0, 0.0), true);
#ifdef PREMULTIPLIED
    e *= texture(albedo, uv * params.tiles).rgb;          // filtered to this resolution
#endif
    lightmap = vec4(e, 1.0);
}
