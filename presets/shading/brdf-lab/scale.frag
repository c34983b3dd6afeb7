#version 450
// Plot scales per entry (x): row 0 the largest table value on both plotted slices (theta_a and
// theta_b, phi = 0 and 180 deg), rows 1 and 2 that of the theta_a and the theta_b slice alone.
#include "entries.glsl"
layout(location = 0) out float plot_scale;
uniform sampler2D table;
int slice_row(float theta_deg) { return clamp(int(round(theta_deg / kStepI)), 0, kNi - 1); }
float slice_max(int e, int row) {
    float s = 1e-30;
    for (int o = 0; o < kNo; ++o) {
        s = max(s, texelFetch(table, ivec2(o, row + kNi * e), 0).r);
        s = max(s, texelFetch(table, ivec2(o + kNo * (kNp / 2), row + kNi * e), 0).r);
    }
    return s;
}
void main() {
    int e = int(gl_FragCoord.x), which = int(gl_FragCoord.y);
    float a = slice_max(e, slice_row(params.theta_a)), b = slice_max(e, slice_row(params.theta_b));
    plot_scale = which == 0 ? max(a, b) : which == 1 ? a : b;
}
