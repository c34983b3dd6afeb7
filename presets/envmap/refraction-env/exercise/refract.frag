#version 450
// EXERCISE — refraction with an environment map (001_fe43b953f362fae7.txt L319-325, L376-380;
// 004_9a40ad89bdfc582a.txt L763-771): the environment seen through the object is bent by
// Snell's law, eta1 sin(theta1) = eta2 sin(theta2), and a part F of the light is reflected
// instead (F the exact Fresnel reflectance, 000 L1108-1118, fresnel_exact(cos_i, n1, n2) in
// passes/common/fresnel.glsl; it returns 1 under total internal reflection).
//     passlab run   envmap/refraction-env --exercise presets/envmap/refraction-env/exercise
//     passlab grade envmap/refraction-env --exercise presets/envmap/refraction-env/exercise
// One refraction only: the ray leaves the object at once (a thin shell). Dispersion refracts
// r, g, b with different etas (m1, m2 per channel below).
#include "common/fresnel.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 0) out vec4 hdr;
layout(location = 1) out float tir;  // 1 where the green channel's ray is totally reflected (tests)
uniform samplerCube env;

void main() {
    vec3 N = normalize(v_normal);
    // TODO 1: the incident direction I (the view ray, from the eye frame.camera_pos.xyz to the
    // surface point v_world; refract() and reflect() expect it as a unit vector), the mirror
    // direction R = I - 2 (N.I) N (001 L251-260), and cos_i, the cosine of the angle of
    // incidence between the ray and the normal, in [0, 1] (mind the sign: I points into the
    // surface).
    vec3 I = vec3(0.0, 0.0, -1.0);
    vec3 R = N;
    float cos_i = 1.0;
    // The media: eta1 = 1 (air) outside, eta2 = eta inside; inside = true swaps them.
    float n1 = params.inside ? params.eta : 1.0, n2 = params.inside ? 1.0 : params.eta;
    vec3 c;
    for (int ch = 0; ch < 3; ++ch) {
        float spread = (float(ch) - 1.0) * params.dispersion;  // r, g, b: eta - d, eta, eta + d
        // m1: the index of the medium the ray comes from, m2: the one it enters.
        float m2 = params.inside ? 1.0 : n2 + spread, m1 = params.inside ? n1 + spread : n1;
        // TODO 2: the refracted direction T by Snell's law (004 L763-771). GLSL's
        // refract(I, N, eta) takes the RATIO of the indices: which one over which? It returns
        // the zero vector where there is no refracted ray (total internal reflection).
        vec3 T = I;
        // TODO 3: the colour of this channel: the environment in direction T and in direction R,
        // mixed by the Fresnel reflectance F of the two media at this incidence (001 L376-380:
        // reflection and refraction together). Where T is the zero vector R is all there is.
        float F = 0.0;
        c[ch] = texture(env, T)[ch];
        if (ch == 1) tir = dot(T, T) == 0.0 ? 1.0 : 0.0;
    }
    hdr = vec4(c, 1.0);
}
