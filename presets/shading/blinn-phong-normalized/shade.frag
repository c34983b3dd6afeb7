#version 450
// Three specular models on one sphere (000_c9f7e5de708ecbb3.txt L912-1020, L1345-1426):
//   phong:      L_o = (c_d cos(theta_i) + c_s (v.r)^m) I_L,       r = 2n(n.l) - l
//   blinn:      L_o = (c_d cos(theta_i) + c_s (n.h)^m) I_L,       h = normalize(v + l)
//   normalized: L_o = pi (c_d/pi + (m+8)/(8pi) c_s (n.h)^m) cos(theta_i) I_L
// Phong's lobe is not energy conserving: a larger m gives a smaller highlight that is no
// brighter. The normalised lobe grows brighter as it shrinks.
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
    vec3 lo;
    if (params.model == MODEL_PHONG) {
        vec3 r = reflect(-l, n);
        float spec = cos_i > 0.0 ? pow(max(dot(v, r), 0.0), m) : 0.0;
        lo = params.diffuse * cos_i + params.specular * spec;
    } else if (params.model == MODEL_BLINN) {
        vec3 h = normalize(v + l);
        float spec = cos_i > 0.0 ? pow(max(dot(n, h), 0.0), m) : 0.0;
        lo = params.diffuse * cos_i + params.specular * spec;
    } else {
        vec3 h = normalize(v + l);
        vec3 f = brdf_lambert(params.diffuse) + params.specular * blinn_phong_normalized(n, h, m);
        lo = kPi * f * cos_i;
    }
    color = vec4(lo, 1.0);
}
