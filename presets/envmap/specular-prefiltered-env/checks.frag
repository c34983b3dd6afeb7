#version 450
// Checks of the prefiltered map against the source it was filtered from, over all 6 x size^2
// texels (both maps are source_size^2: texel centres coincide, so each lookup is one texel):
//   texel 0: max |P - 1|       (with a constant environment of 1 it must stay 1)
//   texel 1: max |P - source|  (with n = 1e4 the lobe is narrower than a texel: P = source)
//   texel 2: max |P - (0.5 + 0.35 (n+1)/(n+2) R)|  for the smooth field L(w) = 0.5 + 0.35 w:
//            the lobe is symmetric about R, so the filtered field is 0.5 + 0.35 E[w], with
//            E[w] = R E[cos] and E[cos] = int cos^(n+1) / int cos^n = (n+1)/(n+2) over the
//            hemisphere around R (the mean of a linear field over the normalised lobe)
#include "envmap/cube.glsl"
#include "envmap/smooth_env.glsl"
layout(location = 0) out float check;
uniform samplerCube prefiltered;
uniform samplerCube env_small;
void main() {
    int size = textureSize(prefiltered, 0).x;
    float dev = 0.0, src = 0.0, lin = 0.0;
    float mean_cos = (params.n + 1.0) / (params.n + 2.0);
    for (int face = 0; face < 6; ++face)
        for (int y = 0; y < size; ++y)
            for (int x = 0; x < size; ++x) {
                vec3 d = cube_face_direction(face, (vec2(x, y) + 0.5) / float(size));
                vec3 p = textureLod(prefiltered, d, 0.0).rgb, s = textureLod(env_small, d, 0.0).rgb;
                vec3 e = abs(p - 1.0), f = abs(p - s), g = abs(p - (0.5 + kSmoothEnvSlope * mean_cos * d));
                dev = max(dev, max(e.r, max(e.g, e.b)));
                src = max(src, max(f.r, max(f.g, f.b)));
                lin = max(lin, max(g.r, max(g.g, g.b)));
            }
    int i = int(gl_FragCoord.x);
    check = i == 0 ? dev : i == 1 ? src : lin;
}
