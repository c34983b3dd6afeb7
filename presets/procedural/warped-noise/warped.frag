#version 450
// Warped noise, 004_9a40ad89bdfc582a.txt L604-615: "sometimes you need different frequencies in
// different parts of the noise image: define polylines where the noise image should contract
// (increases frequency) and move original pixels closer to the borders" (the notes use
// generalized barycentric coordinates for the move; we use a distance-based warp, see below).
//
// Per segment s of the polylines, q_s = the point of s nearest to p, d_s = |p - q_s| and the
// falloff h_s = 1 / (1 + d_s^2 / w^2)^2 (band width w):
//     p' = p + a * sum_s (p - q_s) h_s * (h_s / sum_t h_t)            (warp a)
//     warped(p) = n(p')        n = the base noise, perlin_sum(noise_freq * p) (L315-342)
// The last factor shares the push among the segments that are near: where two segments meet
// they push from the same vertex, and the plain sum would push twice as hard.
// Near one segment the map is radial: r' = r + a w psi(r / w), psi(u) = u / (1 + u^2)^2. At
// the line dr'/dr = 1 + a: the noise of a band (1 + a) times wider is squeezed next to the line,
// its frequency across the line rises by 1 + a (the catalogue: "contract"), and far away
// (u >> 1) p' - p falls off as a w / u^3.
// Pitfalls, stated:
// - A contraction must be paid for by a stretch further out (r' - r -> 0 again): dr'/dr =
//   1 + a psi'(u) has its minimum 1 - a/4 at u = 1. The profile u e^{-u^2} (a Gaussian) pays
//   it in a narrow ring (minimum 1 - 2 a e^{-1.5} = 1 - 0.45 a at u = 1.22), which smears the
//   noise into radial streaks; this one spreads it out.
// - Folding: the map is one-to-one only while dr'/dr > 0, i.e. a < 4 for a straight segment;
//   the corners fold earlier (a = 3: min -0.07), so the param stops at 2.5, and jac (below), the Jacobian determinant of p -> p', is tested > 0.
// - Pushing away from the single nearest point instead: that point jumps across the medial
//   axis (inside corners) and the image tears there; every term and weight here is
//   continuous in p, so p' is.
#include "procedural/noise_ext.glsl"
layout(location = 0) in vec2 uv;
layout(location = 0) out vec4 color;
layout(location = 1) out float warped_out;  // n(p')
layout(location = 2) out float base_out;    // n(p)
layout(location = 3) out float jac_out;     // det(d p' / d p)

// Two polylines in view coordinates (x in [-aspect/2, aspect/2], y in [-1/2, 1/2], y up).
const int kPoints = 9;
const vec2 kPolyline[kPoints] = vec2[](
    vec2(-0.85, -0.05), vec2(-0.45, 0.25), vec2(-0.05, -0.10), vec2(0.35, 0.22), vec2(0.80, 0.0),
    // second polyline (index 5 starts it; segment 4-5 is skipped)
    vec2(-0.70, -0.38), vec2(-0.20, -0.30), vec2(0.25, -0.22), vec2(0.70, -0.36));
const int kBreak = 5;                 // first point of the second polyline
const float kNoiseZ = 0.37;           // the 2D slice of the 3D noise (any non-integer z)

vec2 nearest_on_segment(vec2 p, vec2 a, vec2 b) {
    vec2 ab = b - a;
    return a + ab * clamp(dot(p - a, ab) / dot(ab, ab), 0.0, 1.0);
}

vec2 warp(vec2 p) {
    vec2 push = vec2(0.0);
    float weights = 0.0;  // > 0: h never underflows
    for (int i = 0; i + 1 < kPoints; ++i) {
        if (i + 1 == kBreak) continue;
        vec2 d = p - nearest_on_segment(p, kPolyline[i], kPolyline[i + 1]);
        float u2 = dot(d, d) / (params.width * params.width);
        float h = 1.0 / ((1.0 + u2) * (1.0 + u2));
        push += d * h * h;
        weights += h;
    }
    return p + params.warp * push / weights;
}

float base_noise(vec2 p) { return perlin_sum(vec3(params.noise_freq * p, kNoiseZ), params.octaves, 0.5); }

float polyline_distance(vec2 p) {
    float d = 1e9;
    for (int i = 0; i + 1 < kPoints; ++i)
        if (i + 1 != kBreak) d = min(d, length(p - nearest_on_segment(p, kPolyline[i], kPolyline[i + 1])));
    return d;
}

const float kJacobianStep = 1e-3;  // central differences, view units (w >= 0.02, so h << w)

void main() {
    vec2 p = (uv - 0.5) * vec2(frame.aspect, -1.0);   // view units, y up
    float warped = base_noise(warp(p));
    // The base noise and the Jacobian only when shown or tested (they cost 1 noise + 4 warps).
    float base = 0.0;
    jac_out = 0.0;
    if (params.verify || params.show == SHOW_BASE) base = base_noise(p);
    if (params.verify) {
        vec2 h = vec2(kJacobianStep, 0.0);
        vec2 jx = (warp(p + h.xy) - warp(p - h.xy)) / (2.0 * kJacobianStep);
        vec2 jy = (warp(p + h.yx) - warp(p - h.yx)) / (2.0 * kJacobianStep);
        jac_out = jx.x * jy.y - jx.y * jy.x;
    }
    warped_out = warped;
    base_out = base;

    float v = params.show == SHOW_BASE ? base : warped;
    float t = clamp(0.5 + 0.6 * v, 0.0, 1.0);
    vec3 c = mix(vec3(0.05, 0.07, 0.12), vec3(0.95, 0.85, 0.6), t);
    if (params.show_lines && polyline_distance(p) < 1.5 * frame.resolution.w) c = vec3(0.9, 0.2, 0.1);
    color = vec4(c, 1.0);
}
