#include "image_stats.hpp"

#include <algorithm>
#include <cmath>

namespace pl::lab {

ImageStats image_stats(const image::Image& img, int channel, int bins) {
    ImageStats s;
    const size_t n = static_cast<size_t>(img.width) * img.height;
    if (n == 0 || img.pixels.size() < n * 4) return s;
    s.texels = n;
    std::array<double, 4> sum{};
    s.min.fill(INFINITY);
    s.max.fill(-INFINITY);
    std::vector<float> shown;
    shown.reserve(n);
    for (size_t i = 0; i < n; ++i) {
        const float* p = &img.pixels[i * 4];
        if (!(std::isfinite(p[0]) && std::isfinite(p[1]) && std::isfinite(p[2]) && std::isfinite(p[3]))) {
            ++s.nonfinite;
            continue;
        }
        for (int c = 0; c < 4; ++c) {
            s.min[c] = std::min(s.min[c], p[c]);
            s.max[c] = std::max(s.max[c], p[c]);
            sum[c] += p[c];
        }
        shown.push_back(channel == 0 ? 0.2126f * p[0] + 0.7152f * p[1] + 0.0722f * p[2] : p[std::clamp(channel, 1, 4) - 1]);
    }
    if (shown.empty()) {
        s.min.fill(0.0f), s.max.fill(0.0f);
        return s;
    }
    for (int c = 0; c < 4; ++c) s.mean[c] = static_cast<float>(sum[c] / static_cast<double>(shown.size()));
    const auto [lo, hi] = std::minmax_element(shown.begin(), shown.end());
    s.lo = *lo, s.hi = *hi;
    s.histogram.assign(std::max(1, bins), 0.0f);
    // Linear bins would put a sky at 1 and a sun at 10^4 in the first and last bin: over more
    // than 6 stops of positive values the bins are equal in log2 instead.
    s.log_scale = s.lo > 0.0f && s.hi > 64.0f * s.lo;
    auto key = [&](float v) { return s.log_scale ? std::log2(v) : v; };
    const float k0 = key(s.lo), k1 = key(s.hi);
    const float width = k1 > k0 ? (k1 - k0) / static_cast<float>(s.histogram.size()) : 1.0f;
    for (float v : shown) {
        const size_t b = std::min(s.histogram.size() - 1, static_cast<size_t>(std::max(0.0f, (key(v) - k0) / width)));
        s.histogram[b] += 1.0f;
    }
    // Nearest rank: the smallest value with at least 99% of the texels at or below it.
    const size_t k = static_cast<size_t>(std::ceil(0.99 * static_cast<double>(shown.size()))) - 1;
    std::nth_element(shown.begin(), shown.begin() + static_cast<std::ptrdiff_t>(k), shown.end());
    s.p99 = shown[k];
    return s;
}

float auto_exposure_ev(const ImageStats& s) { return s.p99 > 0.0f ? -std::log2(s.p99) : 0.0f; }

} // namespace pl::lab
