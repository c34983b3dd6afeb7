// The flare billboards of 000_c9f7e5de708ecbb3.txt L3680-3682: "All lens flares lie on the line
// between light source and image center", "rendered with differently sized transparent
// billboards (alpha blending)". Flare i sits at
//   p_i = L + t_i (C - L)        (pixels; L the light on screen, C the image centre)
// t = 0 at the light, 1 at the centre, 2 at the light's mirror image through the centre. The
// table (t, size as a fraction of the view height, colour, shape) is ours; the document only
// names "star, ring or hexagonal shapes" (L3667) and shows two example pictures (L3671-3674).
#ifndef PASSLAB_FLARES_GLSL
#define PASSLAB_FLARES_GLSL
const int kFlares = 8;
const int kDisc = 0, kRing = 1, kHex = 2;
const float kT[kFlares] = float[](0.0, 0.35, 0.6, 0.85, 1.1, 1.35, 1.65, 2.0);
const float kSize[kFlares] = float[](0.25, 0.04, 0.07, 0.03, 0.1, 0.05, 0.14, 0.08);
const vec3 kTint[kFlares] = vec3[](vec3(1.0, 0.75, 0.45), vec3(0.9, 0.6, 0.3), vec3(0.4, 0.8, 0.5), vec3(0.6, 0.5, 1.0),
                                   vec3(0.3, 0.5, 0.9), vec3(1.0, 0.5, 0.6), vec3(0.5, 0.9, 0.9), vec3(0.9, 0.8, 0.4));
const int kShape[kFlares] = int[](kDisc, kDisc, kRing, kHex, kHex, kDisc, kRing, kHex);
const float kAlpha[kFlares] = float[](0.35, 0.5, 0.35, 0.6, 0.3, 0.45, 0.25, 0.35);

// The light in pixels, from its uv position.
vec2 flare_light_px(vec2 light_uv, vec2 res) { return light_uv * res; }
vec2 flare_centre(int i, vec2 light_uv, float spacing, vec2 res) {
    vec2 L = flare_light_px(light_uv, res), C = 0.5 * res;
    return L + (kT[i] * spacing) * (C - L);
}
float flare_radius(int i, float scale, vec2 res) { return kSize[i] * scale * res.y; }  // pixels

// "Happens when light source inside image" (L3666): fade out over the last 5% to the border.
float flare_visibility(vec2 light_uv) {
    vec2 d = min(light_uv, 1.0 - light_uv);
    return clamp(min(d.x, d.y) / 0.05, 0.0, 1.0);
}

// The billboard's shape at q in [-1, 1]^2 (its texture, made procedurally): coverage 0..1.
float flare_shape(int shape, vec2 q) {
    float r = length(q);
    if (shape == kRing) return smoothstep(0.7, 0.8, r) * (1.0 - smoothstep(0.9, 1.0, r));
    if (shape == kHex) {
        vec2 a = abs(q);
        float h = max(a.x * 0.866 + a.y * 0.5, a.y);  // a hexagon with flats at top and bottom
        return 1.0 - smoothstep(0.8, 0.9, h);
    }
    return (1.0 - smoothstep(0.0, 1.0, r)) * (1.0 - smoothstep(0.0, 1.0, r));  // a soft glow
}
#endif
