#version 450
// EXERCISE — three specular models on one sphere (000_c9f7e5de708ecbb3.txt L912-1020).
// Fill in the three TODO blocks, then check your work against the reference:
//     passlab run   shading/blinn-phong-normalized --exercise presets/shading/blinn-phong-normalized/exercise
//     passlab grade shading/blinn-phong-normalized --exercise presets/shading/blinn-phong-normalized/exercise
// All vectors are unit vectors pointing away from the surface: n the normal, l towards the
// light, v towards the eye. cos_i = max(n.l, 0) is computed for you. passes/common/brdf.glsl
// has kPi and brdf_lambert(c_d) = c_d / pi.
#include "common/brdf.glsl"

layout(location = 0) in vec3 v_normal;
layout(location = 1) in vec3 v_world;
layout(location = 0) out vec4 color;

void main() {
    vec3 n = normalize(v_normal);
    vec3 l = normalize(params.light_dir);
    vec3 v = normalize(frame.camera_pos.xyz - v_world);
    float cos_i = max(dot(n, l), 0.0);
    float m = params.shininess;
    vec3 lo = vec3(0.0);
    if (params.model == MODEL_PHONG) {
        // TODO 1: Phong (000 L914, L926):
        //     L_o = (c_d cos(theta_i) + c_s (cos alpha_r)^m) B_L,   cos alpha_r = v.r,
        //     r = 2 n (n.l) - l
        // with c_d = params.diffuse, c_s = params.specular and B_L = 1. Clamp v.r at 0 before
        // the power, and give no highlight where the light is behind the surface (cos_i = 0).
    } else if (params.model == MODEL_BLINN) {
        // TODO 2: Blinn-Phong, unnormalised: the same as TODO 1 with (cos theta_h)^m = (n.h)^m
        // in place of (v.r)^m, where h is the half vector of 000 L1020: h = (v + l) / |v + l|.
    } else {
        // TODO 3: normalised Blinn-Phong, written as a BRDF (000 L1011):
        //     f_r = c_d / pi + (m + 8) / (8 pi) c_s (cos theta_h)^m
        // Reflected radiance from a light of irradiance 1 is L_o = f_r * cos(theta_i) * 1, and the
        // preset scales it by pi so that its diffuse part matches TODO 1 and 2 (c_d cos(theta_i)).
    }
    color = vec4(lo, 1.0);
}
