#version 450
// EXERCISE — specular environment map (001_fe43b953f362fae7.txt L333-341): "prefilter the
// environment map - equals specular integration over the hemisphere - Phong lobe (cos^n) as
// filter kernel - R as lookup". TODO 3 is in exercise/glossy.frag.
//     passlab run   envmap/specular-prefiltered-env --exercise presets/envmap/specular-prefiltered-env/exercise
//     passlab grade envmap/specular-prefiltered-env --exercise presets/envmap/specular-prefiltered-env/exercise
// For every direction R (this texel of face pl_iteration):
//     P(R) = sum_w L(w) max(R.w, 0)^n dw  /  sum_w max(R.w, 0)^n dw
// over every texel w of the 6 x size^2 source, dw its solid angle (cube_texel_solid_angle in
// passes/envmap/cube_texel.glsl). 001 gives no normalisation; the README's "The equation" says
// why the preset divides by the discrete sum of the weights rather than by the lobe's analytic
// integral 2 pi / (n + 1).
// Cost: 6 size^2 terms for each of the 6 size^2 output texels (36 size^4), baked.
#include "envmap/cube_texel.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 prefiltered;
uniform samplerCube env_small;
const float kNegligible = 1e-8;  // lobe weights below this are skipped, in both sums alike (constants stay exact)
const float kMaxTexelSolidAngle = 4.0;  // (2/n)^2 n^2: a bound on dw * size^2 (dw is largest at a face centre)
void main() {
    vec3 R = cube_face_direction(pl_iteration, uv);
    int size = textureSize(env_small, 0).x;
    float n = params.n;
    // c^n dw < kNegligible for every c below c_min: skip those texels before any pow().
    float c_min = pow(kNegligible * float(size * size) / kMaxTexelSolidAngle, 1.0 / n);
    vec3 sum = vec3(0.0);
    float weight = 0.0;
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                vec2 t = (vec2(x, y) + 0.5) / float(size);
                vec3 w = cube_face_direction(face, t);
                float c = dot(R, w);
                if (c <= c_min) continue;
                // TODO 1: the weight k of this source texel: the Phong lobe cos^n about R (c is
                // R.w, already known to be positive here) times the solid angle the texel
                // covers (cube texels near a face corner cover less than those at its centre).
                float k = 0.0;
                if (k < kNegligible) continue;
                // TODO 2: accumulate the numerator and the denominator of P(R) (L(w) is
                // textureLod(env_small, w, 0.0).rgb).
            }
    // TODO 2 (continued): P(R), normalised so that a constant environment stays exactly
    // constant at every n.
    prefiltered = vec4(sum, 1.0);
}
