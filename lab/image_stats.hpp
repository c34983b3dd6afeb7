// What the image viewer says about the image it shows: per-channel min / max / mean over the
// finite texels, how many are NaN or infinite, a histogram of the shown value and its 99th
// percentile, from which auto-exposure picks the EV that maps it to white (HDR images, whose
// range no fixed exposure fits).
#pragma once

#include "image/image.hpp"

#include <array>
#include <cstddef>
#include <vector>

namespace pl::lab {

struct ImageStats {
    std::array<float, 4> min{}, max{}, mean{};  // per channel, finite texels only
    size_t texels = 0, nonfinite = 0;            // texels with a NaN or Inf in any channel
    // The shown value: the channel (1..4 = R, G, B, A) or, for RGB (0), Rec. 709 luminance.
    std::vector<float> histogram;  // counts over [lo, hi] in equal bins (of log2 v when log_scale)
    float lo = 0, hi = 0;
    bool log_scale = false;  // positive values over more than 6 stops (HDR): equal bins in log2
    float p99 = 0;  // 99th percentile of the shown value
};

ImageStats image_stats(const image::Image& img, int channel, int bins = 64);

// The exposure (EV) that maps the 99th percentile of the shown value to 1.0: one bright
// outlier does not darken the picture, and 1% of the texels may clip. 0 when it is not positive.
float auto_exposure_ev(const ImageStats& s);

} // namespace pl::lab
