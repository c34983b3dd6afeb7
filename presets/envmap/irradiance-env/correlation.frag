#version 450
// Pearson correlation between E(N) and max(N.d, 0) over every irradiance texel, d the direction
// of the bright environment texel (face +X, texel (3, 4) of 32).
#include "envmap/cube.glsl"
layout(location = 0) out float corr;
uniform samplerCube irradiance;
void main() {
    vec3 d = cube_face_direction(0, (vec2(3, 4) + 0.5) / 32.0);
    float n = 0.0, sx = 0.0, sy = 0.0, sxx = 0.0, syy = 0.0, sxy = 0.0;
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < 16; ++y)
            for (int x = 0; x < 16; ++x) {
                vec3 N = cube_face_direction(face, (vec2(x, y) + 0.5) / 16.0);
                float a = textureLod(irradiance, N, 0.0).r, b = max(dot(N, d), 0.0);
                n += 1.0, sx += a, sy += b, sxx += a * a, syy += b * b, sxy += a * b;
            }
    float cov = sxy / n - sx * sy / (n * n);
    corr = cov / sqrt(max((sxx / n - sx * sx / (n * n)) * (syy / n - sy * sy / (n * n)), 1e-30));
}
