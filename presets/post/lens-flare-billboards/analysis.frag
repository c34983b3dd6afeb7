#version 450
// Tests, one texel per flare: from the centroid of its pixels (centres at + 0.5),
//   x = distance from the line through the light L and the image centre C (pixels)
//   y = |centroid - p_i|, the error along and across the line (pixels)
//   z = the fragment count, w = the measured t = (centroid - L) . (C - L) / |C - L|^2
#include "flares.glsl"
layout(location = 0) out vec4 flare_check;
layout(std430) readonly buffer centroids { uint sums[]; };
void main() {
    int i = int(gl_FragCoord.x);
    vec2 res = frame.resolution.xy;
    float n = float(sums[3 * i + 2]);
    vec2 c = vec2(float(sums[3 * i]), float(sums[3 * i + 1])) / max(n, 1.0) + 0.5;
    vec2 L = flare_light_px(params.light, res), C = 0.5 * res, d = C - L;
    float across = abs(d.x * (c.y - L.y) - d.y * (c.x - L.x)) / length(d);
    flare_check = vec4(across, length(c - flare_centre(i, params.light, params.spacing, res)), n, dot(c - L, d) / dot(d, d));
}
