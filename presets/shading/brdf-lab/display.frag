#version 450
// Lobe plots as on the slides (000_c9f7e5de708ecbb3.txt L1022-1060, L1175-1240): one panel
// per entry (5 x 3), the plane of incidence seen edge-on, the normal up, the light coming in
// from the left. For a direction at angle psi from the normal (psi > 0: the mirror side,
// phi = 180 deg; psi < 0: the light's side, phi = 0) the lobe's radius is f_r(theta_i, |psi|, phi)
// from the table, linearly interpolated between the 1-degree samples, divided by a scale
// (plot_scale; scale = panel: the larger lobe reaches the rim, scale = lobe: each does).
// Orange: theta_a, cyan: theta_b; the thin lines show where the light comes from. Along the
// top of the panel: the directional albedo a(theta_o) for theta_o = 0..85 deg (white curve;
// the grey line is a = 1, the plot spans 0..1.25).
#include "entries.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
uniform sampler2D table;
uniform sampler2D albedo;
uniform sampler2D plot_scale;

const int kCols = 5, kRows = 3;
const vec3 kColorA = vec3(1.0, 0.55, 0.1), kColorB = vec3(0.15, 0.8, 1.0);

float lobe(int e, int row, float theta_o_deg, int p) {
    float x = clamp(theta_o_deg / kStepO, 0.0, float(kNo - 1));
    int o0 = int(floor(x)), o1 = min(o0 + 1, kNo - 1);
    float a = texelFetch(table, ivec2(o0 + kNo * p, row + kNi * e), 0).r;
    float b = texelFetch(table, ivec2(o1 + kNo * p, row + kNi * e), 0).r;
    return mix(a, b, x - float(o0));
}

// Distance in pixels from point q to the segment a-b.
float segment(vec2 q, vec2 a, vec2 b) {
    vec2 d = b - a;
    return length(q - a - d * clamp(dot(q - a, d) / dot(d, d), 0.0, 1.0));
}

void main() {
    vec2 px = uv * frame.resolution.xy;                  // pixels, y down
    int focus = params.focus;
    vec2 cells = focus >= 0 ? vec2(1.0) : vec2(kCols, kRows);
    vec2 cell = frame.resolution.xy / cells;
    ivec2 ci = ivec2(px / cell);
    int e = focus >= 0 ? focus : ci.x + kCols * ci.y;
    vec3 c = vec3(0.04, 0.04, 0.05);
    if (e >= kEntries) { color = vec4(c, 1.0); return; }
    vec2 q = px - vec2(ci) * cell;                        // pixel within the panel
    float R = min(0.5 * cell.x, 0.72 * cell.y) - 4.0;     // plot radius in pixels
    vec2 origin = vec2(0.5 * cell.x, cell.y - 4.0);
    vec2 d = vec2(q.x - origin.x, origin.y - q.y);        // y up
    float r = length(d) / R;
    float psi = atan(d.x, d.y) / kDegree;                 // degrees from the normal, + to the right
    float thetas[2] = float[](params.theta_a, params.theta_b);
    vec3 cols[2] = vec3[](kColorA, kColorB);
    float pxr = 1.0 / R;                                  // one pixel in plot units
    // the surface and the normal
    if (abs(d.y) < 0.7 && abs(d.x) < R) c = vec3(0.5);
    if (abs(d.x) < 0.5 && d.y > 0.0 && d.y < R) c = vec3(0.25);
    for (int k = 0; k < 2; ++k) {
        int row = clamp(int(round(thetas[k] / kStepI)), 0, kNi - 1);
        float t = float(row) * kStepI;                    // the sampled theta_i
        if (d.y >= 0.0 && r <= 1.0) {
            float s = texelFetch(plot_scale, ivec2(e, params.scale == SCALE_LOBE ? 1 + k : 0), 0).r;
            float f = lobe(e, row, abs(psi), psi > 0.0 ? kNp / 2 : 0) / s;
            if (r < f) c = mix(c, cols[k], 0.35);         // filled lobe
            if (abs(r - f) < 1.2 * pxr) c = cols[k];      // its outline
        }
        vec2 from = origin + R * vec2(-sin(t * kDegree), -cos(t * kDegree));
        if (segment(q, origin, from) < 0.6) c = mix(c, cols[k], 0.8);
    }
    // directional albedo curve across the top of the panel
    float top = 0.24 * cell.y, left = 6.0, width = cell.x - 12.0;
    if (q.y < top + 2.0 && q.x > left && q.x < left + width) {
        float y1 = top - top / 1.25;                      // a = 1
        if (abs(q.y - y1) < 0.5) c = vec3(0.35);
        float xa = (q.x - left) / width * 17.0;
        int a0 = int(floor(xa)), a1 = min(a0 + 1, 17);
        float a = mix(texelFetch(albedo, ivec2(a0, e), 0).r, texelFetch(albedo, ivec2(a1, e), 0).r, xa - float(a0));
        float ya = top - top * a / 1.25;
        if (abs(q.y - ya) < 0.9) c = vec3(1.0);
    }
    // panel border
    if (focus < 0 && (q.x < 1.0 || q.y < 1.0)) c = vec3(0.15);
    color = vec4(c, 1.0);
}
