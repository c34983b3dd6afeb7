// The many-lights scene shared by the deferred presets: point lights placed and coloured by a
// hash of their index, circling slowly, each with a finite radius so a light touches only what
// is near it (which is what makes light volumes and culling possible).
#ifndef PASSLAB_DEFERRED_LIGHTS_GLSL
#define PASSLAB_DEFERRED_LIGHTS_GLSL
#include "common/hash.glsl"

struct PointLight {
    vec3 position;
    vec3 color;
    float radius;
};

PointLight point_light(int i, float time) {
    vec3 h = hash_pcg3(vec3(float(i), 17.0, 3.0));
    float angle = h.x * 6.2831853 + time * (0.2 + 0.3 * h.y);
    float ring = 1.5 + 5.0 * h.z;
    PointLight l;
    l.position = vec3(cos(angle) * ring, 0.3 + 1.2 * h.y, sin(angle) * ring);
    l.color = mix(vec3(1.0, 0.6, 0.3), vec3(0.3, 0.6, 1.0), hash_pcg(vec3(float(i), 5.0, 9.0))) * 1.2;
    l.radius = 2.0 + 1.5 * h.x;
    return l;
}

// Smooth finite falloff: 1 at the light, 0 at its radius and beyond, (1 - (d/r)^2)^2.
float light_falloff(float d, float r) {
    float x = clamp(1.0 - (d * d) / (r * r), 0.0, 1.0);
    return x * x;
}

// x^m for the Blinn-Phong lobe. The deferred presets all use m = 32: five squarings
// (x^2, x^4, x^8, x^16, x^32), the value pow(x, m) = exp2(m log2 x) gives up to rounding, for a
// fraction of its cost on a CPU driver (lavapipe evaluates exp2 and log2 as polynomials, for
// every light at every fragment). m is a compile-time constant at every call, so the test folds.
float lobe_pow(float x, float m) {
    if (m != 32.0) return pow(x, m);
    x *= x; x *= x; x *= x; x *= x;
    return x * x;
}

// Lambert + normalised Blinn-Phong for one light. albedo, specular intensity ks, exponent m.
vec3 shade_point_light(PointLight l, vec3 p, vec3 n, vec3 v, vec3 albedo, float ks, float m) {
    vec3 to_light = l.position - p;
    float d = length(to_light);
    vec3 wl = to_light / max(d, 1e-6);
    float ndl = max(dot(n, wl), 0.0);
    if (ndl <= 0.0) return vec3(0.0);
    vec3 h = normalize(wl + v);
    float spec = ks * (m + 8.0) / 25.1327 * lobe_pow(max(dot(n, h), 0.0), m);  // (m + 8) / (8 pi)
    return (albedo / 3.14159265 + spec) * l.color * ndl * light_falloff(d, l.radius) * 3.14159265;
}
// Debug colour of a light-list length x = count / 64: blue (0) to red (1), clamped; the
// show = count views of deferred/clustered-forward and deferred/forward-many-lights.
vec3 light_count_heat(float x) { return mix(vec3(0.1, 0.2, 0.8), vec3(1.0, 0.15, 0.05), clamp(x, 0.0, 1.0)); }
#endif
