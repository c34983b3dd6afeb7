#version 450
// EXERCISE — Phong vs Blinn-Phong (000_c9f7e5de708ecbb3.txt L912-978, shader L1345-1376).
// Builds on shading/lambert (the diffuse term c_d max(n.l, 0)) and shading/blinn-phong-normalized
// (the half vector and the printed normalised form, which this file calls ready-made).
// Fill in the three TODO blocks, then check your work against the reference:
//     passlab run   shading/phong --exercise presets/shading/phong/exercise   (live, hot reload)
//     passlab grade shading/phong --exercise presets/shading/phong/exercise   (the test cases)
// Write the vectors and lobes yourself: the reference helpers in passes/common/brdf.glsl are the
// answer. Left sphere (v_model == 0): Phong; right sphere: Blinn-Phong.
#include "common/brdf.glsl"
#include "shading/eye_dir.glsl"

layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) flat in int v_model;
layout(location = 0) out vec4 hdr;

void main() {
    vec3 n = normalize(v_normal);               // renormalise the interpolated normal
    vec3 v = eye_dir(v_world);                  // unit vector towards the eye
    // TODO 1: the unit vector l towards the light from params.light_dir (a direction, not
    // necessarily of length 1), and the cosine term cos(theta_i) = max(n.l, 0) (000 L914).
    // Also set lit to 0 where the light is below the horizon (n.l < 0) and 1 elsewhere: the
    // printed shader (L1371) forgets this gate, the reference adds it.
    vec3 l = vec3(0.0, 0.0, 1.0);
    float lambert = 0.0;
    float lit = 0.0;
    float m = params.shininess;
    vec3 lo = vec3(0.0);
    if (v_model == 0) {
        // TODO 2: Phong (000 L912-926, shader L1345-1376):
        //     r = 2 n (n.l) - l                         the mirror direction of l about n
        //     L_o = (c_d cos(theta_i) + c_s (cos alpha_r)^m) B_L,   cos alpha_r = max(v.r, 0)
        // with the specular gated by lit. Read L914 closely: which of the two terms carries
        // the cos(theta_i)?
    } else {
        // TODO 3: Blinn-Phong (000 L980-988, L1020): the half vector h, the unit vector
        // halfway between v and l, and for blinn_form = plain
        //     L_o = (c_d cos(theta_i) + c_s (cos theta_h)^m) B_L,   cos theta_h = max(n.h, 0)
        // with the specular gated by lit.
        vec3 h = vec3(0.0, 0.0, 1.0);
        if (params.blinn_form == BLINN_FORM_PRINTED) {
            // The printed normalised shader (L1378-1409), given: it needs your h and lambert.
            float specular = blinn_phong_normalized(n, h, m) * lit;
            lo = (params.c_d / kPi + params.c_s * specular) * lambert * params.B_L;
        } else {
            // TODO 3 (continued): the plain form.
        }
    }
    hdr = vec4(params.c_e + lo, 1.0);
}
