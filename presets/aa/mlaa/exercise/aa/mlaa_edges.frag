#version 450
// EXERCISE (TODO 1). MLAA step 1, edge detection (000_c9f7e5de708ecbb3.txt L3357: "Edge detection in input
// image"; 003_cfc3b5b225ddab3d.txt L939: "Detect careful designed patterns").
// An edge lies between two pixels whose luma differs by more than a threshold; each pixel
// records the two edges on its left and top boundaries (the other two belong to its right and
// bottom neighbours), as in Jimenez et al.'s GPU MLAA (GPU Pro 2, 2011):
//   edges.r = |Y(p) - Y(p - x)| > threshold      (a vertical edge on p's left side)
//   edges.g = |Y(p) - Y(p - y)| > threshold      (a horizontal edge on p's top side)
// Y is the Rec. 709 luma of the sRGB-encoded colour: MLAA runs on the final image, so edges are
// judged as the display shows them. The first column / row has no neighbour: no edge (so an
// edge never starts at the image border).
// Reads `color`, writes `edges` (bind to rename); THRESHOLD is a float expression
// (e.g. params.threshold).
// LOCAL_CONTRAST (a float expression, default 0 = off): SMAA's local contrast adaptation
// (Jimenez et al. 2012, SMAA_LOCAL_CONTRAST_ADAPTATION_FACTOR = 2): an edge is dropped if a
// neighbouring edge (right, bottom, two to the left / top) is more than this many times as
// strong: a weak edge beside a strong one is usually a shading detail of the strong one, not a
// silhouette of its own.
#include "aa/luma.glsl"
layout(location = 0) out vec4 edges;
uniform sampler2D color;
#ifndef LOCAL_CONTRAST
#define LOCAL_CONTRAST 0.0
#endif
ivec2 g_last;
float luma_at(ivec2 p) { return aa_luma(texelFetch(color, clamp(p, ivec2(0), g_last), 0).rgb); }
void main() {
    g_last = textureSize(color, 0) - 1;
    ivec2 p = ivec2(gl_FragCoord.xy);
    float y = luma_at(p);
    // TODO 1: the two edge strengths of this pixel (000 L3357, "Edge detection in input image").
    // `left` is the difference across p's left side, between p and its neighbour p - x, and
    // `top` across its top side, between p and p - y, each |Y(p) - Y(neighbour)| of the luma Y
    // of the displayed colour (luma_at above; not the colour channels: MLAA judges edges as the
    // eye sees brightness). The first column / row has no neighbour there: strength 0.
    float left = 0.0, top = 0.0;  // replace
    vec2 e = vec2(step(THRESHOLD, left) * step(1e-6, left), step(THRESHOLD, top) * step(1e-6, top));
    float lca = LOCAL_CONTRAST;
    if (lca > 0.0 && e != vec2(0.0)) {
        // The strongest neighbouring difference: to the right and below, and one further out
        // to the left and above (the differences the neighbouring edges of the same pixels see).
        float right = p.x < g_last.x ? abs(y - luma_at(p + ivec2(1, 0))) : 0.0;
        float bottom = p.y < g_last.y ? abs(y - luma_at(p + ivec2(0, 1))) : 0.0;
        float leftleft = p.x > 1 ? abs(luma_at(p - ivec2(1, 0)) - luma_at(p - ivec2(2, 0))) : 0.0;
        float toptop = p.y > 1 ? abs(luma_at(p - ivec2(0, 1)) - luma_at(p - ivec2(0, 2))) : 0.0;
        float strongest = max(max(max(left, top), max(right, bottom)), max(leftleft, toptop));
        e *= step(strongest, lca * vec2(left, top));
    }
    edges = vec4(e, 0.0, 1.0);
}
