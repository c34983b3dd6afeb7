#version 450
// GRID x GRID points, one per vertex (topology = "points"), straight in clip space (w = 1), at
// the centres of a grid of cells over the region REGION (NDC x0, y0, x1, y1), rounded to pixel
// corners so that the emitted triangles' corners are pixel corners too (the coverage test then
// counts exactly). jitter moves each point by a hashed sub-pixel offset in [0, 1) px.
#include "common/hash.glsl"
layout(location = 0) out vec3 v_dummy;   // nothing to pass on: the geometry shader makes the colours
const int GRID = 10;
void main() {
    int i = gl_VertexIndex % GRID, j = gl_VertexIndex / GRID;
    vec4 region = REGION;
    vec2 lo = (region.xy * 0.5 + 0.5) * frame.resolution.xy;      // pixels
    vec2 hi = (region.zw * 0.5 + 0.5) * frame.resolution.xy;
    vec2 px = floor(lo + (vec2(i, j) + 0.5) * (hi - lo) / float(GRID));
    if (params.jitter) px += hash_pcg3(vec3(i, j, 7.0)).xy;
    v_dummy = vec3(0.0);
    gl_Position = vec4(px / frame.resolution.xy * 2.0 - 1.0, 0.5, 1.0);
    if (!(VISIBLE)) gl_Position = vec4(0.0, 0.0, -2.0, 1.0);
}
