#include "viewer_view.hpp"

#include <algorithm>
#include <cmath>

namespace pl::lab {

FitRect fit_rect(int w, int h, int W, int H) {
    FitRect r;
    if (w <= 0 || h <= 0) return r;
    r.scale = std::min(static_cast<float>(W) / w, static_cast<float>(H) / h);
    r.x = (W - w * r.scale) * 0.5f;
    r.y = (H - h * r.scale) * 0.5f;
    return r;
}

FitRect view_rect(const ViewerView& v, int w, int h, int W, int H) { return v.fitted ? fit_rect(w, h, W, H) : v.free; }

void zoom_at(ViewerView& v, const FitRect& current, double steps, float px, float py) {
    // 1/64 (a 4K image in a thumbnail) to 256 texels per pixel (single texels of a small map).
    float s = static_cast<float>(current.scale * std::exp2(steps));
    if (s >= 1.0f) s = std::exp2(std::round(std::log2(s)));
    s = std::clamp(s, 1.0f / 64.0f, 256.0f);
    // The image point under the cursor stays under it: px = x + u * scale before and after.
    const float u = (px - current.x) / current.scale, t = (py - current.y) / current.scale;
    v.free = {px - u * s, py - t * s, s};
    v.fitted = false;
}

void pan_by(ViewerView& v, const FitRect& current, float dx, float dy) {
    v.free = {current.x + dx, current.y + dy, current.scale};
    v.fitted = false;
}

namespace {

// One axis of blit_regions: the cut first texel, the whole texels, the cut last texel.
struct Segment {
    int s0, s1, d0, d1;
};
std::vector<Segment> segments(float origin, float scale, int n, int N) {
    auto pos = [&](int s) { return std::clamp(static_cast<int>(std::lround(origin + s * static_cast<double>(scale))), 0, N); };
    const double first = (0.0 - origin) / scale, last = (N - origin) / scale;
    const int a = std::clamp(static_cast<int>(std::floor(first)), 0, n), b = std::clamp(static_cast<int>(std::ceil(last)), 0, n);
    const int whole0 = std::clamp(static_cast<int>(std::ceil(first - 1e-4)), a, b);
    const int whole1 = std::clamp(static_cast<int>(std::floor(last + 1e-4)), whole0, b);
    std::vector<Segment> out;
    if (whole0 == whole1) {  // no texel wholly inside: each visible texel alone
        for (int s = a; s < b; ++s) out.push_back({s, s + 1, pos(s), pos(s + 1)});
    } else {
        if (a < whole0) out.push_back({a, whole0, pos(a), pos(whole0)});
        out.push_back({whole0, whole1, pos(whole0), pos(whole1)});
        if (whole1 < b) out.push_back({whole1, b, pos(whole1), pos(b)});
    }
    std::erase_if(out, [](const Segment& g) { return g.d1 <= g.d0; });
    return out;
}

} // namespace

std::vector<BlitRegion> blit_regions(const FitRect& r, int w, int h, int W, int H) {
    std::vector<BlitRegion> out;
    if (w <= 0 || h <= 0 || W <= 0 || H <= 0 || !(r.scale > 0.0f)) return out;
    for (const Segment& y : segments(r.y, r.scale, h, H))
        for (const Segment& x : segments(r.x, r.scale, w, W)) out.push_back({x.s0, y.s0, x.s1, y.s1, x.d0, y.d0, x.d1, y.d1});
    return out;
}

std::array<int, 2> texel_at(const FitRect& r, float px, float py) {
    return {static_cast<int>(std::floor((px - r.x) / r.scale)), static_cast<int>(std::floor((py - r.y) / r.scale))};
}

} // namespace pl::lab
