// A procedural solid texture (000_c9f7e5de708ecbb3.txt L1721-1758): T(x, y, z) maps object space
// straight to a colour, so the object is "carved" out of the material: rings continue across
// every edge and through the inside, with no (u, v) at all. The carved-wood function as
// printed (L1746-1754):
//     0 <= x^2 + y^2 < 1  =>  light brown
//     1 <= x^2 + y^2 < 2  =>  dark brown
//     2 <= x^2 + y^2 < 3  =>  yellow          "etc.": the three repeat, band = floor(x^2+y^2) mod 3
// It depends on x and y only: rings around the z axis, the same at every z (the test).
// turbulence > 0 adds gradient noise to x^2 + y^2 (a wood-like wobble; it depends on z, so
// the translation invariance holds for turbulence = 0 only).
#ifndef SOLID_TEXTURE_GLSL
#define SOLID_TEXTURE_GLSL
#include "common/noise.glsl"

const vec3 kLightBrown = vec3(0.45, 0.25, 0.11);
const vec3 kDarkBrown  = vec3(0.17, 0.08, 0.03);
const vec3 kYellow     = vec3(0.75, 0.55, 0.16);

vec3 carved_wood(vec3 p) {
    float r2 = p.x * p.x + p.y * p.y;
    if (params.turbulence > 0.0) r2 += params.turbulence * gradient_noise(p * params.noise_frequency);
    int band = int(floor(r2)) % 3;
    if (band < 0) band += 3;                       // r2 < 0 only through the noise
    return band == 0 ? kLightBrown : band == 1 ? kDarkBrown : kYellow;
}

// Object space -> texture space: scaled (rings per unit) and shifted by tex_offset.
vec3 texture_space(vec3 object_pos) { return object_pos * params.scale + params.tex_offset; }
#endif
