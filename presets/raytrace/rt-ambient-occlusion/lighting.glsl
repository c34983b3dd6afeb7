// precomputed-ao's lighting (its shade.frag, apply = all): I = V (k_a I_a + k_d I_d max(n . l, 0))
// (000_c9f7e5de708ecbb3.txt L4867-4869) with its colours per patch. Shared by the view's shading
// and the test-only per-vertex shading, which differ in where V comes from.
#ifndef RTAO_LIGHTING_GLSL
#define RTAO_LIGHTING_GLSL
vec3 albedo_of(int id) {
    if (id == 0) return vec3(0.75, 0.73, 0.7);
    if (id == 1) return vec3(0.85, 0.35, 0.25);
    if (id == 2) return vec3(0.3, 0.55, 0.85);
    if (id <= 8) return vec3(0.8, 0.75, 0.45);
    return vec3(0.6, 0.8, 0.6);
}

// Towards the directional light (the same for every pixel: shade.vert computes it once per
// vertex of the fullscreen triangle, not once per pixel).
vec3 rtao_light_direction() {
    return normalize(vec3(cos(radians(params.light_elevation)) * cos(radians(params.light_azimuth)),
                          sin(radians(params.light_elevation)),
                          cos(radians(params.light_elevation)) * sin(radians(params.light_azimuth))));
}

vec3 rtao_shade(float v, vec3 n, int id, vec3 l) {
    vec3 kd = albedo_of(id);
    return v * (params.ambient * kd + params.direct * kd * max(dot(n, l), 0.0));
}

vec3 rtao_shade(float v, vec3 n, int id) { return rtao_shade(v, n, id, rtao_light_direction()); }
#endif
