#version 450
// Checks of the prefiltered cube: texel 0 = max |level - 1| over levels 0..5 and 6 x 9
// directions (meaningful for a constant environment of 1); texel 1 = max |level 0 - source|.
// The second channel counts the lookups each maximum was taken over (324 and 54): a loop that
// does not run would report a deviation of 0 and pass, so the tests probe the count too.
#include "envmap/cube.glsl"
layout(location = 0) out vec2 levels;
uniform samplerCube prefiltered;
uniform samplerCube env;
void main() {
    float dev = 0.0, src = 0.0, n_dev = 0.0, n_src = 0.0;
    for (int face = 0; face < 6; ++face)
        for (int k = 0; k < 9; ++k) {
            vec3 d = cube_face_direction(face, (vec2(k % 3, k / 3) + 0.5) / 3.0);
            for (int level = 0; level <= 5; ++level) {
                dev = max(dev, abs(textureLod(prefiltered, d, float(level)).r - 1.0));
                n_dev += 1.0;
            }
            src = max(src, length(textureLod(prefiltered, d, 0.0).rgb - textureLod(env, d, 0.0).rgb));
            n_src += 1.0;
        }
    levels = int(gl_FragCoord.x) == 0 ? vec2(dev, n_dev) : vec2(src, n_src);
}
