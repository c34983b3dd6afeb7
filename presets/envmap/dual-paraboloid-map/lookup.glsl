// The environment in world direction d for the view: through the two paraboloid maps
// (dp_lookup, alpha selects the map) or straight from the cube map (lookup = cube_map). With
// show_maps, what comes from the +z map is tinted warm and what comes from the -z map cool.
#include "envmap/dual_paraboloid.glsl"
uniform samplerCube env;
uniform sampler2DArray maps;
const vec3 kFrontTint = vec3(1.0, 0.75, 0.55), kBackTint = vec3(0.55, 0.75, 1.0);
vec3 environment(vec3 d) {
    if (params.lookup == LOOKUP_CUBE_MAP) return texture(env, d).rgb;
    vec4 c = dp_lookup(maps, d);
    return params.show_maps ? c.rgb * mix(kBackTint, kFrontTint, c.a) : c.rgb;
}
