// The one lighting equation both modes use: Lambert + Blinn-Phong, evaluated per vertex or per
// pixel depending on the mode. The (diffuse, specular) terms are the bump family's
// (passes/bump/lighting.glsl); this preset adds no ambient and weights the highlight 1.
#include "bump/lighting.glsl"
vec3 blinn_phong(vec3 n, vec3 p) {
    // EXERCISE (bump/per-pixel-lighting). TODO 4: l, the unit vector towards the light
    // (params.light_dir is a direction, not necessarily unit length), and v, the unit vector
    // from p to the eye (frame.camera_pos.xyz): bump_blinn_phong_terms takes unit vectors
    // (its half vector h = normalize(l + v) is only the bisector of two unit vectors).
    vec3 l = vec3(0.0, 0.0, 1.0), v = vec3(0.0, 0.0, 1.0);
    vec2 t = bump_blinn_phong_terms(n, l, v, params.shininess);
    return vec3(0.6, 0.35, 0.25) * t.x + vec3(t.y);
}
