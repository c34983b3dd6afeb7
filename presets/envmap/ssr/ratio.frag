#version 450
// The match fractions from the 1x1 top level of `classes` (the mean over the view, exact for
// power-of-two sizes: each level averages 2x2 texels):
//   out = (matching / counted hits, matching / all hits, counted hits, all hits) as fractions
//   of the view
layout(location = 0) out vec4 stats;
uniform sampler2D classes;
void main() {
    vec4 m = textureLod(classes, vec2(0.5), float(textureQueryLevels(classes) - 1));
    stats = vec4(m.y / max(m.x, 1e-9), m.w / max(m.z, 1e-9), m.x, m.z);
}
