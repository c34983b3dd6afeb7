#version 450
// Random directions (one pair per texel): G of Torrance-Sparrow, and the relative change of
// Cook-Torrance's f_r when l and v are swapped (m = 0.24, F0 = 0.9).
#include "common/brdf.glsl"
#include "common/fresnel.glsl"
#include "common/hash.glsl"
layout(location = 0) out vec2 checks;
vec3 upper(vec3 h) {  // a direction in the upper hemisphere around +z
    float c = 0.02 + 0.98 * h.x, s = sqrt(1.0 - c * c), phi = 6.2831853 * h.y;
    return vec3(s * cos(phi), s * sin(phi), c);
}
float f_r(vec3 l, vec3 v) {
    vec3 n = vec3(0, 0, 1), h = normalize(l + v);
    float nl = l.z, nv = v.z, nh = h.z, vh = dot(v, h);
    return ndf_beckmann(nh, 0.24) * fresnel_schlick(vh, 0.9) * g_torrance_sparrow(nh, nv, nl, vh) / (4.0 * nv * nl);
}
void main() {
    vec2 p = gl_FragCoord.xy;
    vec3 l = upper(hash_pcg3(vec3(p, 1.0))), v = upper(hash_pcg3(vec3(p, 2.0)));
    vec3 h = normalize(l + v);
    float G = g_torrance_sparrow(h.z, v.z, l.z, dot(v, h));
    float a = f_r(l, v), b = f_r(v, l);
    checks = vec2(G, abs(a - b) / max(a, 1e-20));
}
