// Fur strands for shells and fins (004_9a40ad89bdfc582a.txt L1067-1134): "render several shells
// (offset surfaces) around the original polygonal geometry ... put different textures on each
// shell" (L1069-1074). The "texture" of shell k is procedural: the surface's uv is cut into
// cells, a cell holds a strand with probability `density`, the strand's length is a per-cell
// random fraction (the seed's "noise texture for length of fur hairs", L1118), and it tapers, so
// shell t (0 at the skin, 1 at the tips) keeps a smaller disc of each cell the higher it is.
#ifndef PASSLAB_FUR_GLSL
#define PASSLAB_FUR_GLSL
#include "common/hash.glsl"

// Coverage of a strand at surface coordinate `st` (cells of 1 x 1) and height t in (0, 1]:
// true where a hair is.
bool fur_strand(vec2 st, float t) {
    vec2 cell = floor(st);
    vec3 h = hash_pcg3(vec3(cell, 17.0));
    if (h.x >= params.density) return false;             // no strand in this cell
    float len = 0.55 + 0.45 * h.y;                        // its length, a fraction of fur_length
    if (t > len) return false;
    vec2 centre = cell + 0.5 + 0.25 * (h.yz - 0.5);
    float radius = 0.45 * (1.0 - t / len);                // tapering to a tip
    return length(st - centre) < radius;
}

// Shading of a strand at height t: the colour darkens towards the skin, a cheap stand-in for the
// self-shadowing the seed asks for (L1120-1124).
vec3 fur_color(float t, float lambert) {
    return params.fur_color * (0.25 + 0.75 * t) * (0.35 + 0.65 * lambert);
}
#endif
