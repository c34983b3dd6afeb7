#include "image/compare.hpp"

#include <algorithm>
#include <cmath>

namespace pl::image {

DiffStats diff(const Image& a, const Image& b, float threshold) {
    DiffStats d;
    if (a.width != b.width || a.height != b.height || a.pixels.size() != b.pixels.size()) {
        d.size_mismatch = true;
        d.rmse = d.max_abs = d.bad_fraction = d.mean_abs = INFINITY;
        return d;
    }
    size_t n = static_cast<size_t>(a.width) * a.height;
    double sq = 0, abs_sum = 0;
    size_t bad = 0;
    for (size_t i = 0; i < n; ++i) {
        double worst = 0;
        for (int c = 0; c < 3; ++c) {
            double e = std::fabs(double(a.pixels[i * 4 + c]) - double(b.pixels[i * 4 + c]));
            if (!std::isfinite(e)) e = 1e9;
            sq += e * e;
            abs_sum += e;
            worst = std::max(worst, e);
        }
        d.max_abs = std::max(d.max_abs, worst);
        bad += worst > threshold;
    }
    d.rmse = std::sqrt(sq / double(n * 3));
    d.mean_abs = abs_sum / double(n * 3);
    d.bad_fraction = double(bad) / double(n);
    return d;
}

Image diff_heatmap(const Image& a, const Image& b) {
    Image h;
    h.width = std::min(a.width, b.width);
    h.height = std::min(a.height, b.height);
    h.pixels.assign(static_cast<size_t>(h.width) * h.height * 4, 1.0f);
    for (int y = 0; y < h.height; ++y)
        for (int x = 0; x < h.width; ++x) {
            float e = 0;
            for (int c = 0; c < 3; ++c) e = std::max(e, std::fabs(a.at(x, y)[c] - b.at(x, y)[c]));
            float t = std::clamp(e / 0.25f, 0.0f, 1.0f);
            float* p = h.at(x, y);
            // black -> blue -> red -> yellow -> white
            p[0] = std::clamp(t * 3.0f - 1.0f, 0.0f, 1.0f);
            p[1] = std::clamp(t * 3.0f - 2.0f, 0.0f, 1.0f) + (t > 0.999f ? 1.0f : 0.0f) * 0;
            p[2] = t < 1.0f / 3.0f ? t * 3.0f : std::clamp(2.0f - t * 3.0f, 0.0f, 1.0f) + (t > 0.95f ? 1.0f : 0.0f);
            p[2] = std::min(p[2], 1.0f);
            p[3] = 1.0f;
        }
    return h;
}

double ssim(const Image& a, const Image& b) {
    if (a.width != b.width || a.height != b.height) return 0.0;
    auto lum = [](const Image& im, int x, int y) {
        const float* p = im.at(x, y);
        return 0.2126 * p[0] + 0.7152 * p[1] + 0.0722 * p[2];
    };
    const double C1 = 0.01 * 0.01, C2 = 0.03 * 0.03;
    double sum = 0;
    int windows = 0;
    for (int y0 = 0; y0 + 8 <= a.height; y0 += 4)
        for (int x0 = 0; x0 + 8 <= a.width; x0 += 4) {
            double ma = 0, mb = 0;
            for (int y = y0; y < y0 + 8; ++y)
                for (int x = x0; x < x0 + 8; ++x) ma += lum(a, x, y), mb += lum(b, x, y);
            ma /= 64, mb /= 64;
            double va = 0, vb = 0, cov = 0;
            for (int y = y0; y < y0 + 8; ++y)
                for (int x = x0; x < x0 + 8; ++x) {
                    double da = lum(a, x, y) - ma, db = lum(b, x, y) - mb;
                    va += da * da, vb += db * db, cov += da * db;
                }
            va /= 63, vb /= 63, cov /= 63;
            sum += ((2 * ma * mb + C1) * (2 * cov + C2)) / ((ma * ma + mb * mb + C1) * (va + vb + C2));
            ++windows;
        }
    return windows ? sum / windows : 1.0;
}

} // namespace pl::image
