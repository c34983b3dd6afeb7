#version 450
// The over operator in a shader (000_c9f7e5de708ecbb3.txt L2041-2146): what the blend unit does
// with (SRC_ALPHA, ONE_MINUS_SRC_ALPHA), written out, for straight and for premultiplied colour,
// on the inputs of the `alpha` cell: source SRC over destination DST (defines).
//   straight:       C = Cs a_s + Cd (1 - a_s),   A = a_s + A_d (1 - a_s)
//   premultiplied:  colour stored as (C a, a); then C' = Cs' + Cd' (1 - a_s), A likewise
// The factor is one minus the SOURCE's alpha: the source covers a_s of the pixel and lets
// 1 - a_s of what is behind through. In premultiplied form the source's colour already carries
// its alpha, so over multiplies only the destination (multiplying Cs' by a_s again would count
// the coverage twice, a_s^2). The alpha channel composes by the same rule in both forms.
// Both targets are rgba32f: no 8-bit rounding, the tests compare with the formula exactly.
layout(location = 0) out vec4 over_out;           // straight over
layout(location = 1) out vec4 over_premul_out;    // premultiplied over (premultiplied result)

vec4 over_straight(vec4 s, vec4 d) {
    return vec4(s.rgb * s.a + d.rgb * (1.0 - s.a), s.a + d.a * (1.0 - s.a));
}

vec4 premultiply(vec4 c) { return vec4(c.rgb * c.a, c.a); }

vec4 over_premultiplied(vec4 s, vec4 d) { return s + d * (1.0 - s.a); }

void main() {
    over_out = over_straight(SRC, DST);
    over_premul_out = over_premultiplied(premultiply(SRC), premultiply(DST));
}
