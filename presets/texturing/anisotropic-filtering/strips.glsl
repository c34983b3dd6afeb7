// Which filter a pixel shows (display.frag) and which ones a pixel must evaluate
// (reference.frag: filter_needed; the filter passes: filter_columns, the plane clipped to them
// in ground.vert). With params.analysis off, each pixel evaluates only the filter(s) of the
// strip(s) within 2 pixels of its column, so the picture is the same as with everything
// evaluated, at a fraction of the cost; the analysis needs all four everywhere.
#ifndef ANISO_STRIPS_GLSL
#define ANISO_STRIPS_GLSL
// The strip shown at horizontal position u in [0, 1] (display.frag's uv.x).
int shown_filter(float u) {
    return params.show == SHOW_SPLIT ? min(int(u * 4.0), 3) : params.show;
}
// True if filter `which` (SHOW_TRILINEAR .. SHOW_REFERENCE) is shown within 2 pixels of this
// fragment's column. The margin makes the answer the same for the two columns of a 2x2 quad
// (implicit derivatives stay defined) and absorbs uv rounding at the strip borders.
bool filter_needed(int which, float frag_x) {
    if (params.analysis) return true;
    float lo = (frag_x - 2.0) * frame.resolution.z, hi = (frag_x + 2.0) * frame.resolution.z;
    int a = shown_filter(clamp(lo, 0.0, 1.0)), b = shown_filter(clamp(hi, 0.0, 1.0));
    return which >= min(a, b) && which <= max(a, b);
}
// The columns [lo, hi] (in uv.x, 0..1) where filter `which` is needed: its strip widened by the
// same 2 pixels as filter_needed; the whole view with params.analysis or when `which` fills the
// view; none when another single filter does. ground.vert clips the plane to them, so the
// filter passes (one per filter) shade only these columns.
vec2 filter_columns(int which) {
    if (params.analysis || params.show == which) return vec2(-1.0, 2.0);
    if (params.show != SHOW_SPLIT) return vec2(2.0, -1.0);
    float m = 2.0 * frame.resolution.z;
    return vec2(float(which) * 0.25 - m, float(which + 1) * 0.25 + m);
}
#endif
