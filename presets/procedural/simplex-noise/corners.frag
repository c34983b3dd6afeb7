#version 450
// |simplex noise| at the corner with skewed coordinates (x - 8, y - 8) of this texel.
#include "common/noise.glsl"
layout(location = 0) out float corners;
void main() { corners = abs(simplex_noise(simplex_corner(floor(gl_FragCoord.xy) - 8.0))); }
