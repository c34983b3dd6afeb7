#version 450
// The tap pattern the gather uses at its largest grid (si = params.max_taps per axis), one tap
// per texel of this (si + 1)^2 image (tests and the `taps` view):
//   (p.x, p.y, |p|^2, how far p lies outside the n-gon of circumradius 1)
// outside = max_k (p . n_k) - cos(pi/n), n_k = (cos 2 pi k/n, sin 2 pi k/n): <= 0 inside.
// And the second moments (p.x^2, p.y^2, p.x p.y): equal and 0 for a pattern without a preferred
// direction (the grid is symmetric under quarter turns; the concentric map keeps that).
#include "bokeh_taps.glsl"
layout(location = 0) out vec4 taps;
layout(location = 1) out vec4 tap_moments;
void main() {
    vec2 s = floor(gl_FragCoord.xy), si = vec2(params.max_taps);
    vec2 p = getBokehTapSampleCoord(bokeh_grid(s, si, params.grid == GRID_CENTRED), params.f_factor, float(params.ngon),
                                    radians(params.shutter), params.ngon_angle == NGON_ANGLE_FIXED);
    float outside = -1e9;
    for (int k = 0; k < params.ngon; ++k) {
        float a = 2.0 * PI * float(k) / float(params.ngon);
        outside = max(outside, dot(p, vec2(cos(a), sin(a))));
    }
    taps = vec4(p, dot(p, p), outside - cos(PI / float(params.ngon)));
    tap_moments = vec4(p.x * p.x, p.y * p.y, p.x * p.y, 0.0);
}
