// rt-soft-shadows: directions towards a sun of angular radius SUN (radians), "choose random
// direction from cone; cone width defines penumbra" (000_c9f7e5de708ecbb3.txt L5771-5775).
// Uniform over the cone's solid angle: cos(theta) uniform in [cos(SUN), 1], phi uniform in
// [0, 2 pi) (the cap's area element is d(cos theta) d(phi)), so a uniform point (u, v) of the unit
// square maps to a uniform direction, and an evenly spread set of points to evenly spread
// directions.
#include "common/hash.glsl"

vec3 sun_disc_direction(vec3 l, float sun, vec2 uv) {
    float cos_t = 1.0 - uv.x * (1.0 - cos(sun));
    float sin_t = sqrt(max(1.0 - cos_t * cos_t, 0.0));
    float phi = 6.28318531 * uv.y;
    vec3 t = normalize(abs(l.y) < 0.99 ? cross(l, vec3(0.0, 1.0, 0.0)) : cross(l, vec3(1.0, 0.0, 0.0)));
    vec3 b = cross(l, t);
    return normalize(sin_t * (cos(phi) * t + sin(phi) * b) + cos_t * l);
}

// Sample k of pixel px: Roberts' R2 sequence (the plastic number g, x_k = frac(s + k (1/g,
// 1/g^2))), a low-discrepancy sequence that needs no sample count in advance, shifted per pixel
// by a random offset (Cranley-Patterson rotation) so neighbouring pixels do not share a pattern.
// Its error over k samples falls about as 1/k where random sampling's falls as 1/sqrt(k).
vec2 sun_disc_sample(ivec2 px, int k) {
    const vec2 a = vec2(0.75487766624669276, 0.56984029099805327);  // 1/g, 1/g^2, g = 1.3247...
    return fract(hash_pcg3(vec3(px, 7.0)).xy + float(k) * a);
}
