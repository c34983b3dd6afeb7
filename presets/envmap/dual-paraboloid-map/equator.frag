#version 450
// The seam: texel i looks up direction (cos phi, sin phi, 0), phi = 2 pi (i + 0.5) / width, in
// BOTH maps (each at its rim, |(s, t)| = 1) and writes the largest difference of their colours
// (un-premultiplied: rgb / alpha, alpha ~ 0.5 at the rim). Bilinear filtering there mixes texels
// up to one texel pitch inside each disc: directions with r_z = +e in one map, -e in the other,
// e <= 2 / map_size radians.
#include "envmap/dual_paraboloid.glsl"
layout(location = 0) out float seam;
uniform sampler2DArray maps;
const int kSamples = 256;  // the width of the seam image
void main() {
    float phi = 6.2831853 * gl_FragCoord.x / float(kSamples);
    vec3 r = vec3(cos(phi), sin(phi), 0.0);
    vec4 a = textureLod(maps, vec3(dp_uv(dp_coord(r, 0)), 0.0), 0.0), b = textureLod(maps, vec3(dp_uv(dp_coord(r, 1)), 1.0), 0.0);
    vec3 d = abs(a.rgb / max(a.a, 1e-6) - b.rgb / max(b.a, 1e-6));
    seam = max(d.r, max(d.g, d.b));
}
