// EXERCISE — light mapping, the run-time half (000_c9f7e5de708ecbb3.txt L2192-2214): the floor's
// colour for each mode, shared by the floor draw and the texel-centre check. The bake is in
// bake.frag (TODO 1, 2).
//   lightmap:      the surface texture and the light map, multitexturing at run time (L2200)
//   per_pixel:     albedo(uv * tiles) * E(p)              the reference, lit every frame (given)
//   lightmap_only: the light map alone
//   premultiplied: the premultiplied map alone (albedo x light baked together by bake.frag)
// The floor has two parametrisations: uv, unique over the floor (each point its own uv, what a
// light map needs: "use single map for group of coplanar polys", L2192-2194), and uv * tiles,
// repeating, which floor.frag uses for the surface texture (albedo_texel is that lookup). The
// light map and the premultiplied map are clamp, linear samplers.
#ifndef LIGHT_MAPPING_FLOOR_GLSL
#define LIGHT_MAPPING_FLOOR_GLSL
#include "lighting.glsl"
vec3 floor_color(int mode, vec2 uv, vec3 albedo_texel) {
    if (mode == MODE_PER_PIXEL) return albedo_texel * irradiance(floor_position(uv), vec3(0.0, 1.0, 0.0), true);
    // TODO 3: the baked maps at this floor point (L2192-2196): read `lightmap` (the light
    // alone) and `premult` (albedo x light) with the parametrisation they were baked over
    // (bake.frag's TODO 1). Which of the floor's two is it?
    if (mode == MODE_LIGHTMAP_ONLY) return texture(lightmap, uv).rgb;
    if (mode == MODE_PREMULTIPLIED) return texture(premult, uv).rgb;
    // TODO 4: the light-mapped colour (L2197-2200, "multitexturing at runtime"): the surface
    // texture's albedo_texel combined with the light map's irradiance E at this point the way
    // the per-pixel reference above combines albedo and light:
    //     L = albedo * E
    return albedo_texel * texture(lightmap, uv).rgb;
}
#endif
