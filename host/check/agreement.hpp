// Partial agreement for image checks (`range`, `matches_pass`): which pixels count (`mask`: an
// image of the same run whose `mask_channel` is nonzero, or zero with `invert_mask`), how many of
// them pass, and the RMSE of a comparison, so "agrees with the reference on >= 99% of the pixels
// outside the edge bands" is one check.
#pragma once

#include "check/args.hpp"
#include "image/image.hpp"

#include <cmath>
#include <functional>
#include <optional>

namespace pl::check {

struct Mask {
    const image::Image* img = nullptr;  // none: every pixel counts
    int channel = 0;
    bool invert = false;
    bool counts(size_t pixel) const {
        if (!img) return true;
        return (img->pixels[pixel * 4 + static_cast<size_t>(channel)] != 0.0f) != invert;
    }
};

struct Agreement {
    size_t counted = 0, passing = 0;
    double worst = 0.0;  // largest per-pixel error of the counted pixels (comparisons)
    double sum_sq = 0.0;
    size_t values = 0;   // channel values in the RMSE
    double fraction() const { return counted ? double(passing) / double(counted) : 0.0; }
    double rmse() const { return values ? std::sqrt(sum_sq / double(values)) : 0.0; }
};

// Tallies the pixels `mask` counts; `pixel_error` returns a pixel's largest channel error (for
// worst and pass/fail against `tol`) and adds squared channel errors to `sum_sq`/`values`.
Agreement tally(size_t pixels, const Mask& mask, double tol,
                const std::function<double(size_t pixel, double& sum_sq, size_t& values)>& pixel_error);

// "N of M counted pixels (F) pass, need >= fraction" for messages; "" without fraction or mask.
std::string describe(const Agreement& a, const Args& args);

} // namespace pl::check
