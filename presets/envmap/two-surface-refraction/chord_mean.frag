#version 450
// The sphere's mean chord errors from the 1x1 top level of `chord` (a mips pass averages it; the
// mean over the view is exact for power-of-two sizes), divided by the sphere's coverage:
//   out = (mean |d - chord| / chord, mean |d - chord| / diameter, coverage, 1)
layout(location = 0) out vec4 chord_stats;
uniform sampler2D chord;
void main() {
    vec4 m = textureLod(chord, vec2(0.5), float(textureQueryLevels(chord) - 1));
    chord_stats = vec4(m.x / max(m.w, 1e-9), m.z / max(m.w, 1e-9), m.w, 1.0);
}
