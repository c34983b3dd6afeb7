#version 450
// Phong vs Blinn-Phong, as the course shows them (000_c9f7e5de708ecbb3.txt):
//   Phong (L912-926, shader L1345-1376):
//       L_o = c_e + (c_d cos(theta_i) + c_s (cos alpha_r)^m) B_L,   cos alpha_r = v.r,
//       r = 2 n (n.l) - l                                            (all vectors normalised)
//   Blinn-Phong, the same with the half vector (L980-988, L1020):
//       L_o = c_e + (c_d cos(theta_i) + c_s (cos theta_h)^m) B_L,   cos theta_h = n.h,
//       h = normalize(v + l)
//   blinn_form = printed: the normalised shader of L1378-1409,
//       L_o = (c_d / pi + (m + 8)/(8 pi) c_s (n.h)^m) cos(theta_i) I_L   (B_L used as I_L)
//
// Pitfall of the printed Phong shader (L1371): the specular term is not gated by n.l, so a
// light below the horizon (n.l < 0) still puts a highlight where v.r > 0 (r = 2n(n.l) - l then
// also points below the horizon, but v near the silhouette can still see it). Here the
// specular is multiplied by step(0, n.l) - stated, not silent. Phong's specular also lacks
// the cos(theta_i) factor its diffuse has (L914): that is why the peak is c_d cos + c_s.
#include "common/brdf.glsl"
#include "shading/eye_dir.glsl"

layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in int v_model;
layout(location = 0) out vec4 hdr;

void main() {
    vec3 n = normalize(v_normal);               // renormalise the interpolated normal
    vec3 v = eye_dir(v_world);
    vec3 l = normalize(params.light_dir);       // towards the light (the shader's -light_direction)
    float lambert = max(dot(n, l), 0.0);
    float lit = step(0.0, dot(n, l));           // pitfall fix: no highlight from below the horizon
    float m = params.shininess;
    vec3 lo;
    if (v_model == 0) {
        vec3 r = phong_mirror(n, l);
        float specular = phong_lobe(v, r, m) * lit;
        lo = (params.c_d * lambert + params.c_s * specular) * params.B_L;
    } else {
        vec3 h = normalize(v + l);
        if (params.blinn_form == BLINN_FORM_PRINTED) {
            float specular = blinn_phong_normalized(n, h, m) * lit;
            lo = (params.c_d / kPi + params.c_s * specular) * lambert * params.B_L;
        } else {
            float specular = blinn_phong_lobe(n, h, m) * lit;
            lo = (params.c_d * lambert + params.c_s * specular) * params.B_L;
        }
    }
    hdr = vec4(params.c_e + lo, 1.0);
}
