#version 450
// EXERCISE — the Cook-Torrance microfacet BRDF (000_c9f7e5de708ecbb3.txt L1132-1256):
//     f_r(l, v) = D(h) F(l, v) G(l, v) / (4 (n.v)(n.l))                      (L1213-1222)
// Builds on shading/phong (the vectors n, l, v, the half vector of Blinn-Phong and the cosine
// term) and shading/fresnel (Schlick's approximation). Fill in the five TODO blocks, then check
// your work against the reference:
//     passlab run   shading/cook-torrance --exercise presets/shading/cook-torrance/exercise
//     passlab grade shading/cook-torrance --exercise presets/shading/cook-torrance/exercise
// Write the terms yourself: ndf_beckmann, g_torrance_sparrow (passes/common/brdf.glsl) and
// fresnel_schlick (passes/common/fresnel.glsl) are the answer. Only the printed Beckmann form
// (ndf = printed) is given. v_m is the sphere's RMS microfacet slope m (0.069, 0.24, 0.5).
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
        // TODO 1: the half vector (L1156-1159): only the microfacets whose normal h lies halfway
        // between l and v mirror l into v. Set h (a unit vector) and the two cosines the terms
        // below need: cos theta_h = n.h and cos alpha_h = v.h (L1199).
        vec3 h = normalize(l + v);
        float nh = dot(n, h), vh = dot(v, h);

        // TODO 2: the microfacet distribution D (L1163-1173), Beckmann with RMS slope m = v_m:
        //     D = exp(((n.h)^2 - 1) / (m^2 (n.h)^2)) / (k m^2 (n.h)^4)
        // The course prints k = 4; then the projected area, the integral of D (n.h) over the
        // hemisphere, is pi/4 instead of 1. ndf = normalized (the default) wants the k that makes
        // it 1. The printed form is given.
        float D = 0.0;
        if (params.ndf == NDF_PRINTED) D = ndf_beckmann_printed(nh, v_m);
        else D = exp((nh * nh - 1.0) / (v_m * v_m * nh * nh)) / (kPi * v_m * v_m * nh * nh * nh * nh);

        // TODO 3: Fresnel (L1122-1130), Schlick's approximation with F0 = params.f0:
        //     F = F0 + (1 - F0)(1 - cos theta)^5
        // theta is the angle of incidence on the surface that does the reflecting. Here that is
        // not the macro-surface of normal n: which normal do the reflecting microfacets have?
        float F = params.f0 + (1.0 - params.f0) * pow(1.0 - vh, 5.0);

        // TODO 4: geometric attenuation, Torrance-Sparrow (L1189-1201), shadowing and masking:
        //     G = min(1, 2 cos theta_h cos theta_o / cos alpha_h, 2 cos theta_h cos theta_i / cos alpha_h)
        // with cos theta_h = n.h, cos theta_o = n.v, cos theta_i = n.l, cos alpha_h = v.h.
        float G = min(1.0, min(2.0 * nh * nv / vh, 2.0 * nh * nl / vh));

        // TODO 5: assemble the specular BRDF f_r = D F G / (4 (n.v)(n.l)) (L1213-1222), then the
        // reflected radiance of the light (irradiance E = params.intensity from l):
        //     L_o = (f_diffuse + f_spec) E cos theta_i,   f_diffuse = brdf_lambert(params.diffuse)
        // Count the cosines: each one belongs in exactly one place.
        float spec = D * F * G / 1.0;
        c = (brdf_lambert(params.diffuse) + vec3(spec)) * params.intensity * nl;
    }
    hdr = vec4(c, 1.0);
}
