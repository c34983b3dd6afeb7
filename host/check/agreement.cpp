#include "check/agreement.hpp"

#include <cmath>

namespace pl::check {

Agreement tally(size_t pixels, const Mask& mask, double tol,
                const std::function<double(size_t pixel, double& sum_sq, size_t& values)>& pixel_error) {
    Agreement a;
    for (size_t i = 0; i < pixels; ++i) {
        if (!mask.counts(i)) continue;
        ++a.counted;
        double e = pixel_error(i, a.sum_sq, a.values);
        if (!std::isfinite(e)) e = INFINITY;  // NaN never agrees
        a.worst = std::max(a.worst, e);
        a.passing += e <= tol;
    }
    return a;
}

std::string describe(const Agreement& a, const Args& args) {
    if (!args.count("fraction") && !args.count("mask")) return "";
    std::string s = std::to_string(a.passing) + " of " + std::to_string(a.counted) + " pixel(s)" +
                    (args.count("mask") ? (num(args, "invert_mask", 0) != 0 ? " outside" : " inside") + std::string(" mask '") + str(args, "mask") + "'" : "") + " pass (" + fmt(a.fraction()) + ")";
    s += args.count("fraction") ? ", need >= " + fmt(num(args, "fraction", 1.0)) : ", need all";
    return s;
}

} // namespace pl::check
