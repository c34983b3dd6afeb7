// Bump mapping from a height field, the original form (Blinn 1978) and its simplifications
// (000_c9f7e5de708ecbb3.txt L2424-2445; 001_fe43b953f362fae7.txt L563-689, L741-780).
//   displaced surface     P'(u, v) = P + h N_n                         (001 L578-595)
//   perturbed normal      N' = P'_u x P'_v ~ N + h_u (N_n x P_v) + h_v (P_u x N_n)   (h small:
//                         the h N_nu, h N_nv terms dropped, 001 L597-619; 000 L2442-2444 prints
//                         the same with -h_v (n x p_u))
//   square patch, in TBN  N' ~ N_n + D,  D = (-h_u / k, -h_v / k, 0)   (001 L741-780)
// h_u, h_v are derivatives of the height in world units per unit of u and v.
#ifndef PASSLAB_BLINN_BUMP_GLSL
#define PASSLAB_BLINN_BUMP_GLSL

// Pitfall (000 L2524-2526 "b = n x t (watch out for handedness!)"): the formula takes N = P_u x P_v. When the
// (u, v) parameterisation is left-handed on the surface (P_u x P_v points inwards: passlab's
// plane and sphere generators are), the offsets must flip sign with it, or every bump is lit
// from the wrong side. handedness w = sign((P_u x P_v) . N_n); N is taken as the smooth normal
// N_n scaled to |P_u x P_v| (analytically equal to w P_u x P_v, without the facets). Returns
// the unnormalised N' (offset normals need renormalising, 001 L741-780 / catalogue pitfall).
vec3 blinn_bump_normal(vec3 N_n, vec3 P_u, vec3 P_v, float h_u, float h_v) {
    vec3 cross_uv = cross(P_u, P_v);
    float w = dot(cross_uv, N_n) < 0.0 ? -1.0 : 1.0;
    return length(cross_uv) * N_n + w * (h_u * cross(N_n, P_v) + h_v * cross(P_u, N_n));
}

// The offset map form in tangent space: N_n = (0, 0, 1) plus D = (-h_u / k, -h_v / k, 0),
// k the bump scale (on a square patch, |P_u| = |P_v| = k). Unnormalised.
vec3 offset_bump_normal_ts(float h_u, float h_v, float k) { return vec3(h_u / k, h_v / k, 1.0); }

// Emboss bump mapping (000 L2477-2478, "simple case"): the derivative of h along the light's
// tangent-space direction from two height lookups, shifted towards the light by `shift` (uv):
//     N'.L ~ l.z - grad(h).l.xy / k ~ l.z + (h(t) - h(t + shift l.xy)) / (shift k)
// first order, never renormalised: the form is only right for gentle slopes.
float emboss_diffuse(float h_here, float h_towards_light, float shift, float k, vec3 l_ts) {
    return l_ts.z + (h_here - h_towards_light) / (shift * k);
}
#endif
