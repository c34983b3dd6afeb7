#version 450
// The rectangle a pass of the anti-aliasing chain draws: the whole view, or with params.crop
// (the live view; not with verify, whose analysis reads whole images) only the texels the
// magnified display shows (passes/aa/zoom.glsl's region) plus MARGIN texels each way.
// MARGIN (an int expression) is how far the rest of the chain reads from this pass's output
// for one displayed texel: each pass is exact inside the region, because everything it reads
// there was computed (edges: 2 texels, the pattern search max_search + 1, weights and blend 1;
// FXAA up to 26.5 texels along an edge plus its bilinear fetch). Outside, the images keep
// whatever they held: nothing displayed depends on it.
// Two triangles, vertices 0..5 (vertex_count = 6); uv as the host's fullscreen stage gives it.
layout(location = 0) out vec2 uv;
#ifndef MARGIN
#define MARGIN 0
#endif
void main() {
    vec2 size = frame.resolution.xy, lo = vec2(0.0), hi = size;
    if (params.crop && !params.verify) {
        // aa_zoom_texel's range: the region's extent (uv) about its kept-inside centre.
        vec2 extent = vec2(params.split ? 0.5 : 1.0, 1.0) / params.zoom;
        vec2 c = clamp(params.centre, 0.5 * extent, 1.0 - 0.5 * extent);
        lo = clamp(floor((c - 0.5 * extent) * size) - float(MARGIN), vec2(0.0), size);
        hi = clamp(floor((c + 0.5 * extent) * size) + 1.0 + float(MARGIN), vec2(0.0), size);
    }
    const vec2 kCorner[6] = vec2[](vec2(0, 0), vec2(1, 0), vec2(0, 1), vec2(1, 0), vec2(1, 1), vec2(0, 1));
    vec2 p = mix(lo, hi, kCorner[gl_VertexIndex]);  // texels; (0, 0) = the top-left corner
    uv = p / size;
    gl_Position = vec4(uv * 2.0 - 1.0, 0.0, 1.0);
}
