// Image comparison for tests: error statistics, a heatmap, and SSIM.
#pragma once

#include "image/image.hpp"

namespace pl::image {

// Over the RGB channels of both images (alpha is ignored: most targets write 1).
struct DiffStats {
    double rmse = 0, max_abs = 0, bad_fraction = 0, mean_abs = 0;
    bool size_mismatch = false;
};

DiffStats diff(const Image& a, const Image& b, float threshold);
// Per-pixel max channel error through a black-blue-red-yellow-white ramp (0 .. 0.25+).
Image diff_heatmap(const Image& a, const Image& b);
// Luminance SSIM, 8x8 windows, C1 = (0.01)^2, C2 = (0.03)^2 (Wang et al. 2004). 1 = identical.
double ssim(const Image& a, const Image& b);

} // namespace pl::image
