// Shadow-map lookups shared by the shadow presets (docs/catalogue.md 3.11): light-space projection,
// depth compare, constant + slope-scale bias, percentage-closer filtering.
//
// Williams' two steps (000_c9f7e5de708ecbb3.txt L4568-4585; 003_cfc3b5b225ddab3d.txt L252-260):
// 1. render the depth seen from the light into a map; 2. per shaded point, compute its depth as
// seen from the light and compare with the map: larger = shadow, about equal = light.
// Visibility convention of every function here: 1 lit, 0 shadowed; outside the map: lit.
#ifndef PASSLAB_SHADOWS_SHADOW_MAP_GLSL
#define PASSLAB_SHADOWS_SHADOW_MAP_GLSL

// Largest tan(theta) the slope-scale bias follows: beyond ~84 degrees the surface is almost
// parallel to the light, N.L shading is ~0 there anyway, and an unbounded bias detaches every
// shadow (000 L4691-4692).
#ifndef SHADOW_MAX_SLOPE
#define SHADOW_MAX_SLOPE 10.0
#endif

// Light-space projection: world point -> (u, v, depth) of the light's map, u, v in [0, 1]
// (texel (0, 0) at uv (0, 0), as the map was rendered), depth in [0, 1].
vec3 shadow_project(mat4 light_view_proj, vec3 p) {
    vec4 c = light_view_proj * vec4(p, 1.0);
    vec3 ndc = c.xyz / c.w;
    return vec3(ndc.xy * 0.5 + 0.5, ndc.z);
}

// World size of one map texel at p: an ortho light's texels are all the same size (height / map
// rows); a perspective light's grow with the distance along its view axis.
float shadow_texel_world(PasslabCamera light, vec3 p, float map_rows) {
    float height = 2.0 / abs(light.proj[1][1]);                   // ortho: ortho_height
    if (light.clip.w != 1.0) height *= -(light.view * vec4(p, 1.0)).z;   // perspective: 2 d tan(fov/2)
    return height / map_rows;
}

// Constant + slope-scale bias (000 L4685-4700), as a world distance to move the shaded point
// towards the light before its depth is compared:
//     b = texel * (constant + slope * tan(theta)),   cos(theta) = N.L
// Why tan: one map texel covers texel * tan(theta) of depth on a surface at angle theta to the
// light, and the shaded point lies up to ~0.71 texel (half a diagonal) from the texel centre the
// map stored, so slope >= 0.71 removes acne from a nearest lookup (a wider filter needs more).
// Too small: acne (000 L4687-4688); too large: Peter Panning, the shadow detaches from its caster
// by ~b along the light (000 L4691-4692).
float shadow_bias_world(float texel_world, float n_dot_l, float constant_texels, float slope_texels) {
    float c = clamp(n_dot_l, 1e-4, 1.0);
    float tan_theta = min(sqrt(1.0 - c * c) / c, SHADOW_MAX_SLOPE);
    return texel_world * (constant_texels + slope_texels * tan_theta);
}

// One depth compare at texel t (nearest, no filtering): 1 if the point's depth z is not beyond
// what the map stored ("if depth larger: shadow", 000 L4584).
float shadow_compare_texel(sampler2D map, ivec2 t, float z) {
    ivec2 size = textureSize(map, 0);
    if (any(lessThan(t, ivec2(0))) || any(greaterThanEqual(t, size)) || z > 1.0) return 1.0;
    return z <= texelFetch(map, t, 0).r ? 1.0 : 0.0;
}

// The hard shadow: the texel under the point.
float shadow_nearest(sampler2D map, vec3 coord) {
    ivec2 t = ivec2(floor(coord.xy * vec2(textureSize(map, 0))));
    return shadow_compare_texel(map, t, coord.z);
}

// Percentage-closer filtering over an n x n block of texels (000 L4670-4677: filter the compare
// results, never the depths; 003 L300-303: "multiple lookups around the coordinate, tabulate
// the fraction in shadow"). The block is the n x n texels whose centres are nearest the point
// (n = 2: the bilinear footprint; n = 4: the 16 lookups of 003 L321), so the result is a
// multiple of 1/n^2.
// For even n the depths come four at a time from textureGather (the 2x2 texels around a texel
// corner, whatever the sampler's filter), the compares still one per texel: the same result
// as n^2 fetches for a quarter of the fetches (texels past the map's edge repeat the edge
// there, per the sampler's clamp, instead of counting as lit).
float shadow_pcf_grid(sampler2D map, vec3 coord, int n) {
    vec2 size = vec2(textureSize(map, 0));
    vec2 s = coord.xy * size;
    ivec2 first = ivec2(floor(s - 0.5 * float(n - 1)));
    float lit = 0.0;
    if (coord.z > 1.0) return 1.0;
    if (n % 2 == 0) {
        for (int j = 0; j < n; j += 2)
            for (int i = 0; i < n; i += 2) {
                vec4 d = textureGather(map, (vec2(first + ivec2(i, j)) + 1.0) / size, 0);
                lit += dot(vec4(lessThanEqual(vec4(coord.z), d)), vec4(1.0));
            }
        return lit / float(n * n);
    }
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) lit += shadow_compare_texel(map, first + ivec2(i, j), coord.z);
    return lit / float(n * n);
}

// The same n x n compares (n <= 8), compare (i, j) weighted by wx[i] * wy[j] of a separable
// kernel whose weights each sum to 1: a weighted percentage closer (gaussian-pcf).
float shadow_pcf_separable(sampler2D map, vec3 coord, int n, float wx[8], float wy[8]) {
    vec2 s = coord.xy * vec2(textureSize(map, 0));
    ivec2 first = ivec2(floor(s - 0.5 * float(n - 1)));
    float lit = 0.0;
    for (int j = 0; j < n; ++j)
        for (int i = 0; i < n; ++i) lit += wx[i] * wy[j] * shadow_compare_texel(map, first + ivec2(i, j), coord.z);
    return lit;
}

// The same weights on both axes.
float shadow_pcf_weighted(sampler2D map, vec3 coord, int n, float w[8]) { return shadow_pcf_separable(map, coord, n, w, w); }

// Gaussian weights of the n texels of one axis of shadow_pcf_separable's block, centred on the
// shaded point, not on the block: texel i's centre lies at i - offset texels from the point, with
// offset = s - first - 0.5 (s the point in texels), so the weights slide with the point and the
// filtered shadow varies continuously instead of in steps of the texel grid.
//     w_i = g(i - offset) / sum_k g(k - offset),   g(x) = exp(-x^2 / (2 sigma^2))
void shadow_gauss_weights(float offset, int n, float sigma, out float w[8]) {
    float sum = 0.0;
    for (int i = 0; i < 8; ++i) {
        float x = float(i) - offset;
        w[i] = i < n ? exp(-x * x / (2.0 * sigma * sigma)) : 0.0;
        sum += w[i];
    }
    for (int i = 0; i < 8; ++i) w[i] /= sum;   // normalised: a lit neighbourhood stays exactly lit
}

// Gaussian PCF: the n x n block around the point with Gaussian weights of width sigma texels.
float shadow_pcf_gaussian(sampler2D map, vec3 coord, int n, float sigma) {
    vec2 s = coord.xy * vec2(textureSize(map, 0));
    vec2 offset = s - floor(s - 0.5 * float(n - 1)) - 0.5;
    float wx[8], wy[8];
    shadow_gauss_weights(offset.x, n, sigma, wx);
    shadow_gauss_weights(offset.y, n, sigma, wy);
    return shadow_pcf_separable(map, coord, n, wx, wy);
}

// Hardware PCF: a sampler with compare = "less_equal" returns (ref <= texel) per texel, and with
// filter = "linear" blends the four compares bilinearly (docs/format.md, sampler `compare`).
float shadow_hardware(sampler2DShadow map, vec3 coord) { return texture(map, coord); }

#endif
