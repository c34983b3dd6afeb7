#version 450
// EXERCISE — the irradiance map (001_fe43b953f362fae7.txt L345-353: "prefilter with cos(); equals
// diffuse integral over hemisphere; N as lookup direction; interpret each pixel of the envmap as
// a light source, sum up"). This file shadows passes/envmap/irradiance_convolve.frag; TODO 2 is
// in exercise/diffuse_ibl.glsl.
//     passlab run   envmap/irradiance-env --exercise presets/envmap/irradiance-env/exercise
//     passlab grade envmap/irradiance-env --exercise presets/envmap/irradiance-env/exercise
// For every direction N of the irradiance map (one texel, face pl_iteration):
//     E(N) = integral over the sphere of L(w) max(N.w, 0) d(omega)
// summed over every texel of the 6 x 32 x 32 environment. cube_texel_solid_angle(t, n)
// (passes/envmap/cube_texel.glsl) is the solid angle d(omega) of the texel at face coordinate t.
#include "envmap/cube_texel.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 irradiance;
uniform samplerCube env;
const int kEnvSize = 32;
void main() {
    vec3 N = cube_face_direction(pl_iteration, uv);
    vec3 E = vec3(0.0);
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < kEnvSize; ++y)
            for (int x = 0; x < kEnvSize; ++x) {
                vec2 t = (vec2(x, y) + 0.5) / float(kEnvSize);
                vec3 w = cube_face_direction(face, t);
                vec3 L = textureLod(env, w, 0.0).rgb;
                // TODO 1: this texel is a small light of radiance L in direction w (L352). Add
                // its contribution to E: the radiance, weighted by the cosine kernel of 001 L349
                // (only the hemisphere around N receives light), times the part of the
                // sphere the texel covers. Cube texels are not all the same size.
            }
    irradiance = vec4(E, 1.0);
}
