// The one lighting equation both modes use: Lambert + Blinn-Phong, evaluated per vertex or per
// pixel depending on the mode. The (diffuse, specular) terms are the bump family's
// (passes/bump/lighting.glsl); this preset adds no ambient and weights the highlight 1.
#include "bump/lighting.glsl"
vec3 blinn_phong(vec3 n, vec3 p) {
    vec3 l = params.light_dir, v = normalize(frame.camera_pos.xyz - p);
    vec2 t = bump_blinn_phong_terms(n, l, v, params.shininess);
    return vec3(0.6, 0.35, 0.25) * t.x + vec3(t.y);
}
