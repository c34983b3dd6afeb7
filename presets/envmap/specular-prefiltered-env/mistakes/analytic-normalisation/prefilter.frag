#version 450
// Specular environment map (001_fe43b953f362fae7.txt L333-341): "prefilter the environment map
// - equals specular integration over the hemisphere - Phong lobe (cos^n) as filter kernel - R as
// lookup". For every direction R (this texel of face pl_iteration):
//     P(R) = sum_w L(w) max(R.w, 0)^n dw  /  sum_w max(R.w, 0)^n dw
// over every texel w of the 6 x size^2 source, dw its solid angle (cube_texel.glsl). A
// Phong surface lit by the whole environment then shades with one lookup, P(R).
// Normalisation: by the discrete sum of the weights (-> 2 pi / (n + 1) in the continuous
// limit, the Phong lobe's integral). It keeps a constant environment exactly constant at every
// n; the analytic 2 pi / (n + 1) does not on a discrete source, and for n = 1e4 (a lobe of
// half-width 0.012 rad, narrower than a texel) it would be off by a large factor.
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
                float k = pow(c, n) * cube_texel_solid_angle(t, size);
                if (k < kNegligible) continue;
                sum += textureLod(env_small, w, 0.0).rgb * k;
                weight += k;
            }
    prefiltered = vec4(sum * (n + 1.0) / 6.28318530718, 1.0);  // the Phong lobe integrates to 2 pi / (n + 1)
}
