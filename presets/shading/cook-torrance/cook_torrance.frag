#version 450
// Cook-Torrance (000_c9f7e5de708ecbb3.txt L1132-1256):
//     f_r(l, v) = D(h) F(l, v) G(l, v) / (4 (n.v)(n.l))
// D: Beckmann (L1163-1173; printed 4 m^2 or normalised pi m^2, passes/common/brdf.glsl),
// G: Torrance-Sparrow (L1189-1201), F: Schlick with F0. Plus a small Lambert term.
#include "common/brdf.glsl"
#include "common/fresnel.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in float v_m;
layout(location = 0) out vec4 hdr;
void main() {
    vec3 n = normalize(v_normal), l = normalize(params.light_dir), v = normalize(frame.camera_pos.xyz - v_world);
    float nl = dot(n, l), nv = dot(n, v);
    vec3 c = vec3(0.0);
    if (nl > 0.0 && nv > 0.0) {
        vec3 h = normalize(l + v);
        float nh = dot(n, h), vh = dot(v, h);
        float D = params.ndf == NDF_PRINTED ? ndf_beckmann_printed(nh, v_m) : ndf_beckmann(nh, v_m);
        float F = fresnel_schlick(vh, params.f0);
        float G = g_torrance_sparrow(nh, nv, nl, vh);
        float spec = D * F * G / (4.0 * nv * nl);
        c = (brdf_lambert(params.diffuse) + vec3(spec)) * params.intensity * nl;
    }
    hdr = vec4(c, 1.0);
}
