// EXERCISE — a procedural solid texture (000_c9f7e5de708ecbb3.txt L1721-1758): T(x, y, z) maps
// object space straight to a colour, so the object is "carved" out of the material: rings
// continue across every edge and through the inside, with no (u, v) at all. You write the
// carved-wood function as printed (TODO 1, 2, L1746-1754); shade.frag chooses the point it is
// evaluated at (TODO 3).
//     passlab run   texturing/solid-texture-3d --exercise presets/texturing/solid-texture-3d/exercise
//     passlab grade texturing/solid-texture-3d --exercise presets/texturing/solid-texture-3d/exercise
// turbulence > 0 adds gradient noise to the ring coordinate (given; it depends on z).
#ifndef SOLID_TEXTURE_GLSL
#define SOLID_TEXTURE_GLSL
#include "common/noise.glsl"

const vec3 kLightBrown = vec3(0.45, 0.25, 0.11);
const vec3 kDarkBrown  = vec3(0.17, 0.08, 0.03);
const vec3 kYellow     = vec3(0.75, 0.55, 0.16);

vec3 carved_wood(vec3 p) {
    // TODO 1: the ring coordinate of the printed function (L1746-1754): the squared distance
    // from the rings' axis, the z axis (x = y = 0), so that T is the same at every z:
    //     r2 = x^2 + y^2
    float r2 = p.x * p.x + p.z * p.z;
    if (params.turbulence > 0.0) r2 += params.turbulence * gradient_noise(p * params.noise_frequency);
    // TODO 2: the bands as printed (L1746-1754), "etc." read as repeating the three:
    //     0 <= r2 < 1  =>  light brown
    //     1 <= r2 < 2  =>  dark brown
    //     2 <= r2 < 3  =>  yellow,   3 <= r2 < 4 light brown again, ...
    // mind the edges (r2 = 1 exactly is dark brown), and that the noise can make r2 negative.
    int band = int(floor(r2)) % 3;
    if (band < 0) band += 3;
    return band == 0 ? kLightBrown : band == 1 ? kDarkBrown : kYellow;
}

// Object space -> texture space: scaled (rings per unit) and shifted by tex_offset.
vec3 texture_space(vec3 object_pos) { return object_pos * params.scale + params.tex_offset; }
#endif
