// Back-to-front "over" compositing (000_c9f7e5de708ecbb3.txt L4318: "Blend fragments back
// to front"; the over operator, glBlendFunc(GL_SRC_ALPHA, GL_ONE_MINUS_SRC_ALPHA), L2132): c <- a * rgb + (1 - a) * c, starting from the
// opaque colour behind the nearest opaque surface and ending with the nearest fragment.
vec3 oit_over(vec3 dst, vec4 src) { return mix(dst, src.rgb, src.a); }
