// The floor's colour for each mode, shared by the floor draw and the texel-centre check.
//   lightmap:      albedo(uv * tiles) * lightmap(uv)      multitexturing at run time (L2200)
//   per_pixel:     albedo(uv * tiles) * E(p)              the reference, lit every frame
//   lightmap_only: lightmap(uv)
//   premultiplied: premult(uv), albedo x light baked together at the light map's resolution
#ifndef LIGHT_MAPPING_FLOOR_GLSL
#define LIGHT_MAPPING_FLOOR_GLSL
#include "lighting.glsl"
vec3 floor_color(int mode, vec2 uv, vec3 albedo_texel) {
    if (mode == MODE_PER_PIXEL) return albedo_texel * irradiance(floor_position(uv), vec3(0.0, 1.0, 0.0), true);
    if (mode == MODE_LIGHTMAP_ONLY) return texture(lightmap, uv).rgb;
    if (mode == MODE_PREMULTIPLIED) return texture(premult, uv).rgb;
    return albedo_texel * texture(lightmap, uv).rgb;
}
#endif
