// The magnified, optionally split view of the anti-aliasing presets: which texel of a
// view-sized image the display pixel at uv shows. split: both halves show the same region
// (half as wide); left_half tells the caller to show its comparison image there. The region
// (1/zoom of the view, centred at `centre`, uv) is kept inside the image.
#ifndef PASSLAB_AA_ZOOM_GLSL
#define PASSLAB_AA_ZOOM_GLSL
ivec2 aa_zoom_texel(vec2 uv, bool split, float zoom, vec2 centre, vec2 size, out bool left_half) {
    left_half = split && uv.x < 0.5;
    vec2 local = split ? vec2(fract(uv.x * 2.0), uv.y) : uv;
    vec2 extent = vec2(split ? 0.5 : 1.0, 1.0) / zoom;  // the region's size (uv)
    vec2 q = clamp(centre, 0.5 * extent, 1.0 - 0.5 * extent) + (local - 0.5) * extent;
    return clamp(ivec2(floor(q * size)), ivec2(0), ivec2(size) - 1);
}
// The split's divider line.
bool aa_zoom_divider(vec2 uv, bool split) { return split && abs(uv.x - 0.5) < 0.0015; }
#endif
