#version 450
// MLAA step 1, edge detection (000_c9f7e5de708ecbb3.txt L3357: "Edge detection in input
// image"; 003_cfc3b5b225ddab3d.txt L937-940: "detect carefully designed patterns").
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
#include "common/color.glsl"
layout(location = 0) out vec4 edges;
uniform sampler2D color;
float luma_at(ivec2 p) { return luminance(linear_to_srgb(clamp(texelFetch(color, p, 0).rgb, 0.0, 1.0))); }
void main() {
    ivec2 p = ivec2(gl_FragCoord.xy);
    float y = luma_at(p);
    float left = p.x > 0 ? abs(y - luma_at(p - ivec2(1, 0))) : 0.0;
    float top = p.y > 0 ? abs(y - luma_at(p - ivec2(0, 1))) : 0.0;
    edges = vec4(step(THRESHOLD, left) * step(1e-6, left), step(THRESHOLD, top) * step(1e-6, top), 0.0, 1.0);
}
