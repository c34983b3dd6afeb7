#version 450
// MLAA step 2a, pattern classification (000_c9f7e5de708ecbb3.txt L3358: "distance to line
// end/crossing and line shape"; Reshetov 2009, cited in 003_cfc3b5b225ddab3d.txt L937-959).
// For each edge of a pixel, walk along it both ways to the ends of the edge line (at most
// MAX_SEARCH pixels each way) and look at the crossing edges there: an end where the silhouette
// steps up or down by one pixel row (column) is half of an L, Z or U shape. Per pixel:
//   hpat = (d_left, d_right, e_left, e_right)   for its top (horizontal) edge
//   vpat = (d_up,   d_down,  e_up,   e_down)    for its left (vertical) edge
// d = how many pixels the edge line continues beyond this one; e = the end's crossing edges:
//   e = pos + 2 neg,  pos = a crossing edge on the positive side (above a horizontal edge, left
//   of a vertical one), neg = on the negative side (below / right). 0: none, 1: pos, 2: neg,
//   3: both (a T or a cross: no single step to reconstruct).
// An end the search did not reach (d = MAX_SEARCH) counts as e = 0: a longer line is treated as
// straight there, as the GPU implementations do with their bounded searches.
// A pixel without that edge writes zeros (e = 0 at both ends: no blending).
// Reads `edges` (r: edge on the left side, g: on the top side; aa/mlaa_edges.frag).
layout(location = 0) out vec4 hpat;
layout(location = 1) out vec4 vpat;
uniform sampler2D edges;
#ifndef MAX_SEARCH
#define MAX_SEARCH 16
#endif

ivec2 g_size;
// The edge flag `comp` (0: left side, 1: top side) of pixel q; 0 outside the image.
float edge_at(ivec2 q, int comp) {
    if (any(lessThan(q, ivec2(0))) || any(greaterThanEqual(q, g_size))) return 0.0;
    return texelFetch(edges, q, 0)[comp];
}
// How many pixels beyond p along dir still carry edge `comp`.
int search(ivec2 p, ivec2 dir, int comp) {
    int d = 0;
    for (int i = 1; i <= MAX_SEARCH; ++i) {
        if (edge_at(p + dir * i, comp) < 0.5) break;
        d = i;
    }
    return d;
}
// The crossing code of an end, from the crossing edge flags on its positive and negative side.
float crossing(float pos, float neg, int d) { return d >= MAX_SEARCH ? 0.0 : step(0.5, pos) + 2.0 * step(0.5, neg); }

void main() {
    g_size = textureSize(edges, 0);
    ivec2 p = ivec2(gl_FragCoord.xy);
    vec4 e = texelFetch(edges, p, 0);
    hpat = vec4(0.0);
    vpat = vec4(0.0);
    if (e.g > 0.5) {  // top edge, between rows p.y - 1 and p.y, running along x
        int dl = search(p, ivec2(-1, 0), 1), dr = search(p, ivec2(1, 0), 1);
        int xa = p.x - dl, xb = p.x + dr + 1;  // the line's ends: x = xa and x = xb (pixel boundaries)
        // Crossing edges are vertical edges on those boundaries, in the row above (pos) or below (neg).
        float el = crossing(edge_at(ivec2(xa, p.y - 1), 0), edge_at(ivec2(xa, p.y), 0), dl);
        float er = crossing(edge_at(ivec2(xb, p.y - 1), 0), edge_at(ivec2(xb, p.y), 0), dr);
        hpat = vec4(dl, dr, el, er);
    }
    if (e.r > 0.5) {  // left edge, between columns p.x - 1 and p.x, running along y
        int du = search(p, ivec2(0, -1), 0), dd = search(p, ivec2(0, 1), 0);
        int ya = p.y - du, yb = p.y + dd + 1;
        // Crossing edges are horizontal edges on y = ya, yb, in the column left (pos) or right (neg).
        float eu = crossing(edge_at(ivec2(p.x - 1, ya), 1), edge_at(ivec2(p.x, ya), 1), du);
        float ed = crossing(edge_at(ivec2(p.x - 1, yb), 1), edge_at(ivec2(p.x, yb), 1), dd);
        vpat = vec4(du, dd, eu, ed);
    }
}
