#version 450
// Tabulates every entry over (theta_i, theta_o, phi) (entries.glsl for the sampling):
//   table[o + kNo p, i + kNi e] = f_r(l(theta_i, 0), v(theta_o, phi))
// and checks two of the BRDF properties of 000_c9f7e5de708ecbb3.txt L814-828 (= L5000-5007)
// at every sample:
//   reciprocity  f_r(w1, w2) = f_r(w2, w1):  recip = |f(l, v) - f(v, l)| / max(1, f(l, v), f(v, l))
//   positivity   f_r >= 0: the table itself (range check).
// The error is absolute where f <= 1 and relative above: a float holds a value near 100 (the
// sharp Beckmann lobe at grazing angles) only to 7.6e-6, so an absolute 1e-5 there would test
// the rounding of the two evaluations (v.h vs l.h), not the formula.
// The printed Phong shader's entry writes recip = 0 here and f(l, v) / f(v, l) to
// recip_printed instead: (v.r)^m / (n.l) swapped is (v.r)^m / (n.v), a ratio of cos theta_o /
// cos theta_i where the lobe is non-zero.
#include "entries.glsl"
layout(local_size_x = 8, local_size_y = 8) in;
layout(r32f) uniform writeonly image2D table;
layout(r32f) uniform writeonly image2D recip;
layout(r32f) uniform writeonly image2D recip_printed;

void main() {
    ivec2 q = ivec2(gl_GlobalInvocationID.xy);
    if (q.x >= kNo * kNp || q.y >= kNi * kEntries) return;
    int o = q.x % kNo, p = q.x / kNo, i = q.y % kNi, e = q.y / kNi;
    vec3 v = brdf_dir(kStepI * float(i) * kDegree, 0.0);
    vec3 l = brdf_dir(kStepO * float(o) * kDegree, kStepP * float(p) * kDegree);
    float a = entry_brdf(e, l, v), b = entry_brdf(e, v, l);
    imageStore(table, q, vec4(a));
    if (e == kPrintedEntry) {
        imageStore(recip, q, vec4(0.0));
        imageStore(recip_printed, ivec2(q.x, i), vec4(a > 0.0 && b > 0.0 ? a / b : 1.0));
    } else {
        imageStore(recip, q, vec4(abs(a - b) / max(1.0, max(a, b))));
    }
}
