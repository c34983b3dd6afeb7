// The bump family's lighting, in one place: Lambert + Blinn-Phong with the constants of
// presets/bump/normal-mapping/shade.frag (ambient 0.08, specular weight `ks`), so presets that
// must equal normal mapping (bump/horizon-mapping) can call the same code:
//     c = albedo (0.08 + max(l.n, 0)) + ks max(h.n, 0)^s     (specular only where l.n > 0)
// (000_c9f7e5de708ecbb3.txt L2543-2553: max(l.n', 0) and max(h.n', 0)^s, "combine using the
// standard Phong equation"). n, l, v unit vectors in any one space.
#ifndef PASSLAB_BUMP_LIGHTING_GLSL
#define PASSLAB_BUMP_LIGHTING_GLSL
const float kBumpAmbient = 0.08;  // a little light where l.n <= 0, so the relief never goes black

// (diffuse, specular) factors, before albedo and weights.
vec2 bump_blinn_phong_terms(vec3 n, vec3 l, vec3 v, float shininess) {
    vec3 h = normalize(l + v);
    float diff = max(dot(l, n), 0.0);
    return vec2(diff, diff > 0.0 ? pow(max(dot(h, n), 0.0), shininess) : 0.0);
}
vec3 bump_combine(vec3 albedo, float diff, float spec, float ks) { return albedo * (kBumpAmbient + diff) + vec3(ks * spec); }
vec3 bump_blinn_phong(vec3 n, vec3 l, vec3 v, vec3 albedo, float shininess, float ks) {
    vec2 t = bump_blinn_phong_terms(n, l, v, shininess);
    return bump_combine(albedo, t.x, t.y, ks);
}
#endif
