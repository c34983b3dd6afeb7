// Checks that look at one rendered image (and possibly another image of the same run):
// probe, no_nan, range, mean, symmetry, white_furnace, matches_pass.
#pragma once

#include "check/args.hpp"
#include "check/checks.hpp"
#include "image/image.hpp"

#include <functional>

namespace pl::check {

// Returns another image of the same run by name (for matches_pass).
using ImageLookup = std::function<Result<const image::Image*>(const std::string&)>;

// nullopt if `kind` is not an image property.
std::optional<CheckResult> image_property(const image::Image& img, const graph::CheckDesc& c, const ImageLookup& other);

// Largest absolute difference over `chans` of two same-size images (infinity if sizes differ).
double max_difference(const image::Image& a, const image::Image& b, const std::vector<int>& chans);

} // namespace pl::check
