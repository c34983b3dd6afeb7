#version 450
// Ashikhmin-Shirley anisotropic Phong (2000), the course's brushed-metal example
// (000_c9f7e5de708ecbb3.txt L1258-1265: "viewing direction considered, not just inclination",
// n_v = 10; the slide shows a picture, no formula). passes/common/brdf.glsl:
//   f_spec = sqrt((e_u + 1)(e_v + 1)) / (8 pi) (n.h)^((e_u (h.t)^2 + e_v (h.b)^2) / (1 - (n.h)^2))
//            / ((h.l) max(n.l, n.v)) F(h.l),        F = R_s + (1 - R_s)(1 - h.l)^5
//   f_diff = 28 R_d / (23 pi) (1 - R_s) (1 - (1 - n.l/2)^5) (1 - (1 - n.v/2)^5)
//   L_o = (f_spec + f_diff) E cos(theta_i)
// t, b from the mesh's generated tangent, Gram-Schmidt against the interpolated normal.
#include "common/brdf.glsl"
#include "shading/eye_dir.glsl"
layout(location = 0) in vec3 v_world;
layout(location = 1) in vec3 v_normal;
layout(location = 2) in vec4 v_tangent;
layout(location = 3) flat in int v_instance;
layout(location = 0) out vec4 hdr;
void main() {
    vec3 n = normalize(v_normal);
    vec3 t = normalize(v_tangent.xyz - n * dot(n, v_tangent.xyz));
    vec3 b = cross(n, t) * (v_tangent.w < 0.0 ? -1.0 : 1.0);
    vec3 v = eye_dir(v_world), l = normalize(params.light_dir);
    float nl = dot(n, l), nv = dot(n, v);
    float e_u = params.n_u, e_v = v_instance == 0 ? params.n_u : params.n_v;
    vec3 c = params.ambient * params.metal;   // fill light, not part of the BRDF
    if (nl > 0.0 && nv > 0.0) {
        float spec = ashikhmin_shirley_spec(n, t, b, l, v, e_u, e_v, params.R_s);
        vec3 diff = ashikhmin_shirley_diffuse(params.R_d, params.R_s, nl, nv);
        c += (params.metal * spec + diff) * params.light * nl;
    }
    hdr = vec4(c, 1.0);
}
