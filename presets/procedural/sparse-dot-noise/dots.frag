#version 450
// Sparse dot noise (spot noise), 004_9a40ad89bdfc582a.txt L490-502:
//   a regular grid; 4 random numbers r1..r4 per cell;
//   if r1 > threshold the cell has a dot of radius r2 (here r2 * max_radius) at centre (r3, r4);
//   fragment colour = black if |fragment - centre| < radius.
// Three placements, all evaluated per pixel (masks.rgb), the display shows params.placement:
//   inside:     centre = r + (1 - 2r) (r3, r4): the dot lies inside its cell, so nothing clips it
//               and no two dots overlap. The covered fraction is then, in expectation,
//                   P(r1 > t) * E[pi r^2] = (1 - t) * pi R^2 / 3     (r = r2 R, r2 uniform)
//   printed:    centre = (r3, r4) anywhere in the cell, only the own cell tested: a dot that
//               reaches over the border is cut off there, so the grid shows (L499: "improve it,
//               so that the grid is not noticeable").
//   neighbours: the same dots, but the 3x3 neighbouring cells are tested too, so dots cross
//               cell borders whole (R <= 1 keeps every dot within one cell of its own).
// masks.a = neighbours - printed: each printed dot is a subset of the same whole dot, so >= 0.
#include "common/hash.glsl"
layout(location = 0) in vec2 uv;
#ifdef AREAS
layout(location = 0) out float area;   // one texel per cell
#else
layout(location = 0) out vec4 color;
layout(location = 1) out vec4 masks;
#endif

// The cell's r1..r4 (two PCG3D hashes: one gives three numbers).
vec4 cell_randoms(vec2 cell) {
    float s = float(params.seed);
    return vec4(hash_pcg3(vec3(cell, 2.0 * s)), hash_pcg(vec3(cell, 2.0 * s + 1.0)));
}

// 1 if p lies in the dot of `cell` (if it has one), centres placed as described above.
float in_dot(vec2 p, vec2 cell, bool inside) {
    vec4 r = cell_randoms(cell);
    if (r.x <= params.threshold) return 0.0;                 // L495: a dot only if r1 > threshold
    float radius = r.y * params.max_radius;                  // L496: radius = r2 (scaled)
    vec2 centre = inside ? radius + (1.0 - 2.0 * radius) * r.zw : r.zw;  // (r3, r4)
    return length(p - (cell + centre)) < radius ? 1.0 : 0.0;  // L497
}

const float kPi = 3.14159265358979;

#ifdef AREAS
// The area pi r^2 of the cell's dot (0 without one): the mean over cells is the sample value
// of P(r1 > t) E[pi r^2] for exactly the cells drawn, which the pixel coverage must match.
void main() {
    vec4 r = cell_randoms(floor(gl_FragCoord.xy));
    float radius = r.y * params.max_radius;
    area = r.x > params.threshold ? kPi * radius * radius : 0.0;
}
#else
void main() {
    vec2 p = gl_FragCoord.xy * frame.resolution.w * params.cells;  // cell units (pixel centres), cells per view height
    vec2 cell = floor(p);
    float inside = in_dot(p, cell, true);
    float printed = in_dot(p, cell, false);
    float neighbours = 0.0;
    for (int y = -1; y <= 1; ++y)
        for (int x = -1; x <= 1; ++x) neighbours = max(neighbours, in_dot(p, cell + vec2(x, y), false));
    masks = vec4(inside, printed, neighbours, neighbours - printed);

    float ink = params.placement == PLACEMENT_INSIDE ? inside : params.placement == PLACEMENT_PRINTED ? printed : neighbours;
    vec3 c = mix(params.paper, params.ink, ink);
    if (params.show_grid && min(fract(p.x), fract(p.y)) < 0.02 * params.cells / 12.0) c *= 0.85;
    color = vec4(c, 1.0);
}
#endif
