#version 450
// Every tap offset the gather can use, baked once per parameter change: row si - 2 (si = 2..16
// taps per axis) holds the (si + 1)^2 taps of that grid, tap (sx, sy) at x = sy (si + 1) + sx.
// 002 evaluates getBokehTapSampleCoord (a pow, two cosines, a sine) for every tap of every
// pixel; the pattern depends only on si and the params, so a table gives the same offsets at
// one fetch per tap.
#include "bokeh_taps.glsl"
layout(location = 0) out vec4 tap_table;
void main() {
    int i = int(gl_FragCoord.x);
    float si = gl_FragCoord.y - 0.5 + 2.0;
    int row = int(si) + 1;
    if (i >= row * row) {
        tap_table = vec4(0.0);
        return;
    }
    vec2 s = vec2(i % row, i / row);
    vec2 p = getBokehTapSampleCoord(bokeh_grid(s, vec2(si), params.grid == GRID_CENTRED), params.f_factor, max(3.0, float(params.ngon)),
                                    radians(params.shutter), params.ngon_angle == NGON_ANGLE_FIXED);
    tap_table = vec4(p, 0.0, 1.0);
}
