// Compositing operators of the OIT family.
//
// Back-to-front "over" (000_c9f7e5de708ecbb3.txt L4318: "Blend fragments back to front"; the
// over operator, glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA), L2132):
// c <- a * rgb + (1 - a) * c, starting from the opaque colour behind the nearest opaque surface
// and ending with the nearest fragment.
vec3 oit_over(vec3 dst, vec4 src) { return mix(dst, src.rgb, src.a); }

// Front-to-back "under" (depth peeling composites its layers nearest first, L4166-4181; the
// same operator as the hybrid resolve's, 002_644d46bdce7e5305.txt L1811-1813): the accumulator
// holds premultiplied colour and coverage, acc += (a * rgb, a) * (1 - acc.a). The blend state
// { one_minus_dst_alpha, one } does the same in hardware on a premultiplied (a * rgb, a) source.
vec4 oit_under(vec4 acc, vec4 src) { return acc + vec4(src.rgb * src.a, src.a) * (1.0 - acc.a); }

// What is behind an under-accumulator shows through its remaining transmittance 1 - acc.a.
vec3 oit_under_resolve(vec4 acc, vec3 behind) { return acc.rgb + (1.0 - acc.a) * behind; }
