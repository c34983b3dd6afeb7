#include "check/properties.hpp"

#include <cmath>
#include <limits>

namespace pl::check {

double max_difference(const image::Image& a, const image::Image& b, const std::vector<int>& chans) {
    if (a.width != b.width || a.height != b.height) return std::numeric_limits<double>::infinity();
    double worst = 0.0;
    size_t n = static_cast<size_t>(a.width) * a.height;
    for (size_t i = 0; i < n; ++i)
        for (int ch : chans) {
            size_t k = i * 4 + static_cast<size_t>(ch);
            double d = std::fabs(double(a.pixels[k]) - double(b.pixels[k]));
            if (!std::isfinite(d)) return std::numeric_limits<double>::infinity();
            worst = std::max(worst, d);
        }
    return worst;
}

namespace {

CheckResult probe(const image::Image& img, const graph::CheckDesc& c) {
    CheckResult r;
    auto uv = vec(c.args, "uv"), px = vec(c.args, "px"), expect = vec(c.args, "expect");
    double tol = num(c.args, "tol", 0.01);
    int x = 0, y = 0;
    if (uv.size() == 2) {
        // uv (0.5/w, 0.5/h) is the centre of texel (0,0).
        x = std::clamp(static_cast<int>(std::floor(uv[0] * img.width)), 0, img.width - 1);
        y = std::clamp(static_cast<int>(std::floor(uv[1] * img.height)), 0, img.height - 1);
        r.what = "probe uv=(" + fmt(uv[0]) + "," + fmt(uv[1]) + ")";
    } else if (px.size() == 2) {
        x = static_cast<int>(px[0]);
        y = static_cast<int>(px[1]);
        r.what = "probe px=(" + std::to_string(x) + "," + std::to_string(y) + ")";
        if (x < 0 || y < 0 || x >= img.width || y >= img.height) {
            r.detail = "pixel outside the " + std::to_string(img.width) + "x" + std::to_string(img.height) + " image";
            return r;
        }
    } else {
        r.what = "probe";
        r.detail = "needs uv = [u, v] or px = [x, y]";
        return r;
    }
    if (expect.empty() || expect.size() > 4) {
        r.detail = "needs expect = [1 to 4 values]";
        return r;
    }
    // expect[k] is channel k, or with channel/channels the k-th channel named there.
    std::vector<int> chans;
    if (c.args.count("channel") || c.args.count("channels")) chans = channels(c.args);
    else
        for (size_t k = 0; k < expect.size(); ++k) chans.push_back(static_cast<int>(k));
    if (chans.size() != expect.size()) {
        r.detail = "expect has " + std::to_string(expect.size()) + " value(s) for " + std::to_string(chans.size()) + " channel(s)";
        return r;
    }
    const float* p = img.at(x, y);
    double worst = 0.0;
    std::string got;
    for (size_t k = 0; k < expect.size(); ++k) {
        int ch = chans[k];
        if (ch < 0 || ch > 3) {
            r.detail = "channel " + std::to_string(ch) + " does not exist (0..3)";
            return r;
        }
        double d = std::fabs(p[ch] - expect[k]);
        worst = std::isfinite(d) ? std::max(worst, d) : INFINITY;
        got += (k ? "," : "") + fmt(p[ch]);
    }
    r.passed = worst <= tol;
    r.detail = "got (" + got + "), max error " + fmt(worst) + " (tol " + fmt(tol) + ")";
    return r;
}

} // namespace

std::optional<CheckResult> image_property(const image::Image& img, const graph::CheckDesc& c, const ImageLookup& other) {
    if (c.kind == "probe") return probe(img, c);
    CheckResult r;
    r.what = c.kind;
    auto chans = channels(c.args);
    size_t n = static_cast<size_t>(img.width) * img.height;
    if (c.kind == "no_nan") {
        // NaN and Inf both fail: a float target shows them, an 8-bit one would hide NaN as 0.
        size_t bad = 0;
        for (float v : img.pixels) bad += !std::isfinite(v);
        r.passed = bad == 0;
        r.detail = std::to_string(bad) + " NaN/Inf value(s)";
        return r;
    }
    if (c.kind == "range" || c.kind == "white_furnace") {
        double lo, hi;
        if (c.kind == "range") {
            lo = num(c.args, "min", 0.0), hi = num(c.args, "max", 1.0);
        } else {
            // A white furnace: a surface lit by a uniform environment of radiance `expect` must
            // reflect exactly that if it conserves energy and does not absorb.
            double e = num(c.args, "expect", 1.0), t = num(c.args, "tol", 0.01);
            lo = e - t, hi = e + t;
        }
        double mn = INFINITY, mx = -INFINITY;
        bool finite = true;
        for (size_t i = 0; i < n; ++i)
            for (int ch : chans) {
                double v = img.pixels[i * 4 + static_cast<size_t>(ch)];
                finite = finite && std::isfinite(v);
                mn = std::min(mn, v);
                mx = std::max(mx, v);
            }
        r.passed = finite && mn >= lo && mx <= hi;
        r.detail = "values in [" + fmt(mn) + ", " + fmt(mx) + "], allowed [" + fmt(lo) + ", " + fmt(hi) + "]" +
                   (finite ? "" : ", NaN/Inf present");
        return r;
    }
    if (c.kind == "mean") {
        double sum = 0.0;
        for (size_t i = 0; i < n; ++i)
            for (int ch : chans) sum += img.pixels[i * 4 + static_cast<size_t>(ch)];
        double mean = sum / static_cast<double>(n * chans.size());
        double expect = num(c.args, "expect", 0.0), tol = num(c.args, "tol", 0.01);
        r.passed = std::fabs(mean - expect) <= tol;
        r.detail = "mean " + fmt(mean) + ", expected " + fmt(expect) + " ± " + fmt(tol);
        return r;
    }
    if (c.kind == "symmetry") {
        // Mirror symmetry across the vertical (axis = "x": left/right) or horizontal centre line.
        std::string axis = str(c.args, "axis", "x");
        double tol = num(c.args, "tol", 1e-3), worst = 0.0;
        for (int y = 0; y < img.height; ++y)
            for (int x = 0; x < img.width; ++x) {
                const float* a = img.at(x, y);
                const float* b = axis == "y" ? img.at(x, img.height - 1 - y) : img.at(img.width - 1 - x, y);
                for (int ch : chans) {
                    double d = std::fabs(double(a[ch]) - double(b[ch]));
                    worst = std::isfinite(d) ? std::max(worst, d) : INFINITY;  // NaN never passes
                }
            }
        r.what = "symmetry " + axis;
        r.passed = worst <= tol;
        r.detail = "max difference to the mirror image " + fmt(worst) + " (tol " + fmt(tol) + ")";
        return r;
    }
    if (c.kind == "matches_pass") {
        std::string name = str(c.args, "other");
        r.what = "matches_pass " + name;
        auto o = other(name);
        if (!o) {
            r.detail = o.error().message;
            return r;
        }
        double worst = max_difference(img, **o, chans), tol = num(c.args, "tol", 1e-3);
        r.passed = worst <= tol;
        r.detail = "max difference " + fmt(worst) + " (tol " + fmt(tol) + ")";
        return r;
    }
    return std::nullopt;
}

} // namespace pl::check
