#version 450
// Refraction with an environment map (001_fe43b953f362fae7.txt L319-325, L376-380;
// 004_9a40ad89bdfc582a.txt L763-771):
//     T = refract(I, N, eta1/eta2)    (Snell: eta1 sin(theta1) = eta2 sin(theta2))
//     R = reflect(I, N)
//     color = mix(env(T), env(R), F)   F the exact Fresnel reflectance (common/fresnel.glsl)
// One refraction only: the ray leaves the object at once (a thin shell); two-surface refraction
// is envmap/two-surface-refraction. Where refract returns the zero vector (total internal
// reflection) R is all there is (F = 1). Dispersion refracts r, g, b with different etas.
#include "common/fresnel.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
layout(location = 1) out float tir;  // 1 where the green channel's ray is totally reflected (tests)
uniform samplerCube env;

void main() {
    vec3 N = normalize(v_normal), I = normalize(v_world - frame.camera_pos.xyz);
    float n1 = params.inside ? params.eta : 1.0, n2 = params.inside ? 1.0 : params.eta;
    vec3 R = reflect(I, N);
    float cos_i = clamp(-dot(I, N), 0.0, 1.0);
    vec3 c;
    for (int ch = 0; ch < 3; ++ch) {
        float spread = (float(ch) - 1.0) * params.dispersion;  // r, g, b: eta - d, eta, eta + d
        float m2 = params.inside ? 1.0 : n2 + spread, m1 = params.inside ? n1 + spread : n1;
        vec3 T = refract(I, N, m2 / m1);
        float F = dot(T, T) == 0.0 ? 1.0 : fresnel_exact(cos_i, m1, m2);
        vec3 t = dot(T, T) == 0.0 ? vec3(0.0) : texture(env, T).rgb;
        c[ch] = mix(t[ch], texture(env, R)[ch], F);
        if (ch == 1) tir = dot(T, T) == 0.0 ? 1.0 : 0.0;
    }
    hdr = vec4(c, 1.0);
}
