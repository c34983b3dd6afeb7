// Which filter a pixel shows (display.frag) and which ones a pixel must evaluate
// (filter.frag, reference.frag). With params.analysis off, each pixel evaluates only the
// filter(s) of the strip(s) within 2 pixels of its column, so the picture is the same as with
// everything evaluated, at a fraction of the cost; the analysis needs all four everywhere.
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
#endif
