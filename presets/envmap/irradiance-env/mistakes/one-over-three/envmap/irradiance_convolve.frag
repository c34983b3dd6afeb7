#version 450
// The irradiance map (001_fe43b953f362fae7.txt L345-353): for every direction N,
//     E(N) = integral over the sphere of L(w) max(N.w, 0) d(omega)
// summed over every texel of the 6 x 32 x 32 environment (solid angle per texel from
// cube_texel.glsl). Lighting a Lambert surface is then one lookup: L_o = albedo / pi * E(N).
// 6144 terms per output texel, 1536 texels: the cost is why real engines bake this once (or use
// spherical harmonics), and why the map is small: E is smooth.
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
                float c = dot(N, w);
                if (c > 0.0) E += textureLod(env, w, 0.0).rgb * c * cube_texel_solid_angle(t, kEnvSize);
            }
    irradiance = vec4(E, 1.0);
}
