#version 450
// MLAA step 2b, blending weights (000_c9f7e5de708ecbb3.txt L3358: "compute blending texture
// based on distance to line end/crossing and line shape"; Reshetov 2009, 003 L937-959:
// "hallucinate a smooth edge").
// An edge line of n = d1 + d2 + 1 pixels runs from t = 0 to t = n (t along the line, this pixel
// covering [d1, d1 + 1]). Each end with a one-sided crossing edge is a step of the silhouette;
// the reconstructed silhouette passes through the middle of that step, at height
//   h_end = +0.5 (step on the positive side: above / left),  -0.5 (negative side),  0 (none,
//   both, or beyond the search),
// and through the middle of the line, h(n/2) = 0. The shapes (Reshetov's L, Z and U):
//   (0, h1) -> (n/2, 0) -> (n, h2): for a Z (h1 = -h2 != 0) one straight line from step to
//   step; for a U (h1 = h2) a tent; for an L (one end 0) a line to the middle and nothing after.
// The area between the edge and h(t) over this pixel's column is the fraction of the pixel that
// lies on the far side of the reconstructed silhouette. Where h > 0 the silhouette bulges into
// the positive neighbour (the pixel above / left): that neighbour takes a_pos of this pixel's
// colour; where h < 0 this pixel takes a_neg of the neighbour's colour. Both parts are kept
// (the middle pixel of an odd Z has both; the GPU area textures keep only the larger).
// Steps: a Z of length 1 whose crossing edges belong to a longer perpendicular line is not a
// silhouette of its own but one step of that line (the vertical unit steps of a 1:4 staircase),
// whose own Z already covers it: counting it again would blend the step pixels twice (by 1/8
// each side, measured: the staircase error drops 54% with it and more without it). Such steps are
// skipped. Our rule, stated: Reshetov reconstructs per edge line, the GPU area textures blend
// them as Z's of length 1. At 45 degrees both directions are length 1 and both blend.
// weights = (a_neg top: p takes from above, a_pos top: above takes from p,
//            a_neg left: p takes from the left, a_pos left: left takes from p).
// Reads `hpat`, `vpat` (aa/mlaa_patterns.frag).
layout(location = 0) out vec4 weights;
uniform sampler2D hpat;
uniform sampler2D vpat;

const float kStepHeight = 0.5;  // the middle of a one-pixel step
float end_height(float e) { return e == 1.0 ? kStepHeight : (e == 2.0 ? -kStepHeight : 0.0); }

// (positive part, negative part) of the integral of the line through (t0, h0), (t1, h1) over
// [a, b] clipped to [t0, t1].
vec2 line_parts(float t0, float h0, float t1, float h1, float a, float b) {
    float lo = max(a, t0), hi = min(b, t1);
    if (hi <= lo) return vec2(0.0);
    float ha = mix(h0, h1, (lo - t0) / (t1 - t0)), hb = mix(h0, h1, (hi - t0) / (t1 - t0)), len = hi - lo;
    if (ha >= 0.0 && hb >= 0.0) return vec2(0.5 * (ha + hb) * len, 0.0);
    if (ha <= 0.0 && hb <= 0.0) return vec2(0.0, -0.5 * (ha + hb) * len);
    float r = ha / (ha - hb) * len;  // where the line crosses the edge
    return ha > 0.0 ? vec2(0.5 * ha * r, -0.5 * hb * (len - r)) : vec2(0.5 * hb * (len - r), -0.5 * ha * r);
}

// (a_pos, a_neg) for the pixel at distance d1 from the line's start.
vec2 pixel_area(vec4 pat) {
    float d1 = pat.x, n = pat.x + pat.y + 1.0, h1 = end_height(pat.z), h2 = end_height(pat.w);
    float a = pat.y, b = pat.y + 1.0;  // MISTAKE: the distance to the other end
    // Both halves; for a Z the two are one straight line (it passes through (n/2, 0)).
    return line_parts(0.0, h1, 0.5 * n, 0.0, a, b) + line_parts(0.5 * n, 0.0, n, h2, a, b);
}

ivec2 g_size;
vec4 pat_at(sampler2D s, ivec2 q) {
    return any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, g_size)) ? vec4(0.0) : texelFetch(s, q, 0);
}
float line_length(vec4 pat) { return pat.x + pat.y + 1.0; }
bool is_unit_z(vec4 pat) { return pat.x == 0.0 && pat.y == 0.0 && pat.z + pat.w == 3.0 && pat.z * pat.w == 2.0; }

// Whether the unit Z `pat` of p's top edge (horizontal) / left edge (vertical) is a step of a
// longer perpendicular line. Crossing code 1 = positive side (row above / column left).
bool top_is_step(ivec2 p, vec4 pat) {
    // Left end x = p.x: the left edge of (p.x, row); right end x = p.x + 1: of (p.x + 1, row).
    int row_l = pat.z == 1.0 ? p.y - 1 : p.y, row_r = pat.w == 1.0 ? p.y - 1 : p.y;
    return max(line_length(pat_at(vpat, ivec2(p.x, row_l))), line_length(pat_at(vpat, ivec2(p.x + 1, row_r)))) > 1.0;
}
bool left_is_step(ivec2 p, vec4 pat) {
    // Top end y = p.y: the top edge of (column, p.y); bottom end y = p.y + 1: of (column, p.y + 1).
    int col_t = pat.z == 1.0 ? p.x - 1 : p.x, col_b = pat.w == 1.0 ? p.x - 1 : p.x;
    return max(line_length(pat_at(hpat, ivec2(col_t, p.y))), line_length(pat_at(hpat, ivec2(col_b, p.y + 1)))) > 1.0;
}

void main() {
    g_size = textureSize(hpat, 0);
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 h = texelFetch(hpat, p, 0), v = texelFetch(vpat, p, 0);
    vec2 top = is_unit_z(h) && top_is_step(p, h) ? vec2(0.0) : pixel_area(h);
    vec2 left = is_unit_z(v) && left_is_step(p, v) ? vec2(0.0) : pixel_area(v);
    weights = vec4(top.y, top.x, left.y, left.x);
}
