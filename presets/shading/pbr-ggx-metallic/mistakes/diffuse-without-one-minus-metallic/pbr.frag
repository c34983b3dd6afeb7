#version 450
// EXERCISE — the physically based model of 002_644d46bdce7e5305.txt L82-310 (after Karis, "Real
// Shading in Unreal Engine 4"): a GGX microfacet specular and a Lambert diffuse, with the base
// colour split between them by metallic:
//     f(l, v) = diffuse / pi + D(h) F(v, h) V(l, v)
// Builds on shading/cook-torrance (the microfacet BRDF D F G / (4 (n.l)(n.v)), Schlick's Fresnel)
// and shading/lambert (the 1/pi). Fill in the four TODO blocks, then check your work:
//     passlab run   shading/pbr-ggx-metallic --exercise presets/shading/pbr-ggx-metallic/exercise
//     passlab grade shading/pbr-ggx-metallic --exercise presets/shading/pbr-ggx-metallic/exercise
// Write D and F yourself: ndf_ggx (passes/common/brdf.glsl) is the answer. The visibility terms
// v_smith_ggx and v_schlick_ggx (002 L198-250) are given. v_material = (metallic, roughness r).
#include "common/brdf.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in vec2 v_material;
layout(location = 0) out vec4 hdr;

// TODO 3: Schlick's Fresnel (002 L168-196; 000 L1122-1130) for an RGB reflectance at normal
// incidence f0, at the cosine c between the direction of incidence and the reflecting normal:
//     F = mix(vec3(0.08 * params.specular), params.base_color, metallic) + (1 - mix(vec3(0.08 * params.specular), params.base_color, metallic))(1 - c)^5
// (002's listing uses an exp2 fit of the same curve; write the plain form.)
vec3 schlick(vec3 f0, float c) { return f0 + (1.0 - f0) * pow(1.0 - c, 5.0); }

// TODO 2: the GGX / Trowbridge-Reitz distribution as 002 writes it (L130-165), for the
// perceptual roughness r:
//     D = a^2 / (pi ((n.h)^2 (a^2 - 1) + 1)^2)
// where a is not r itself: read the first line of 002's specularD (L159-165).
float ggx(float nh, float r) {
    float a = r * r, a2 = a * a;
    float d = nh * nh * (a2 - 1.0) + 1.0;
    return a2 / (kPi * d * d);
}

void main() {
    float metallic = v_material.x, r = v_material.y;
    vec3 n = normalize(v_normal), l = normalize(params.light_dir), v = normalize(frame.camera_pos.xyz - v_world);
    vec3 h = normalize(l + v);
    // n.l and n.v clamped to [1e-5, 1] as in 002 L265-268.
    float nl = clamp(dot(n, l), 1e-5, 1.0), nv = clamp(dot(n, v), 1e-5, 1.0), nh = max(dot(n, h), 0.0), vh = max(dot(v, h), 0.0);

    // TODO 1: split the base colour (params.base_color, "albedo, NOT diffuse", 002 L91) by
    // metallic (002 L275-276):
    //   - diffuse: the colour the Lambert term scatters. Metals have no diffuse light.
    //   - f0, the Fresnel reflectance at normal incidence: 0.08 x params.specular (about 4 % for
    //     a dielectric) at metallic 0, the base colour itself at metallic 1, blended between.
    vec3 diffuse = params.base_color;
    vec3 f0 = mix(vec3(0.08 * params.specular), params.base_color, metallic);

    float V = params.visibility == VISIBILITY_SMITH_GGX ? v_smith_ggx(nv, nl, r) : v_schlick_ggx(nv, nl, r);

    // TODO 4: the specular BRDF D F V with your ggx (TODO 2) and schlick (TODO 3, at v.h), and the
    // light's reflected radiance (irradiance params.intensity from l; no light from below):
    //     direct = (diffuse / pi + spec) E cos(theta_l)
    // V is 002's Smith term: compare L114's f = D F G / (4 (n.l)(n.v)) with the listings at
    // L228-250 — what does V hold besides G?
    vec3 spec = ggx(nh, r) * schlick(f0, vh) * V;
    vec3 direct = (diffuse / kPi + spec) * params.intensity * (dot(n, l) > 0.0 ? nl : 0.0);

    vec3 ambient = params.ambient * (diffuse + schlick(f0, nv));  // given: a uniform sky
    hdr = vec4(direct + ambient, 1.0);
}
