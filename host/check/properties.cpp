#include "check/properties.hpp"

#include "check/agreement.hpp"

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

std::string size_text(const image::Image& i) { return std::to_string(i.width) + "x" + std::to_string(i.height); }

// The check's `mask` (an image of the same run, the subject's size), or none.
Result<Mask> mask_of(const graph::CheckDesc& c, const image::Image& subject, const ImageLookup& other) {
    Mask m;
    if (!c.args.count("mask")) return m;
    auto img = other(str(c.args, "mask"));
    if (!img) return img.error();
    if ((*img)->width != subject.width || (*img)->height != subject.height)
        return make_error("mask '" + str(c.args, "mask") + "' is " + size_text(**img) + ", the image " + size_text(subject));
    m.img = *img;
    m.channel = static_cast<int>(num(c.args, "mask_channel", 0));
    m.invert = num(c.args, "invert_mask", 0) != 0;
    return m;
}

// range with partial agreement: a pixel passes when every channel lies in [lo, hi].
CheckResult range(const image::Image& img, const graph::CheckDesc& c, const std::vector<int>& chans, const Mask& mask,
                  double lo, double hi) {
    CheckResult r;
    r.what = c.kind;
    double mn = INFINITY, mx = -INFINITY;
    bool finite = true;
    Agreement a = tally(img.pixels.size() / 4, mask, 0.0, [&](size_t i, double&, size_t&) {
        double e = 0;
        for (int ch : chans) {
            double v = img.pixels[i * 4 + static_cast<size_t>(ch)];
            finite = finite && std::isfinite(v);
            mn = std::min(mn, v), mx = std::max(mx, v);
            e = std::max({e, lo - v, v - hi});
            if (!std::isfinite(v)) e = INFINITY;
        }
        return e;
    });
    r.passed = a.counted > 0 && a.fraction() >= num(c.args, "fraction", 1.0);
    // No counted pixel (a mask that selects none) has no values to show: say so instead of [inf, -inf].
    r.detail = (a.counted ? "values in [" + fmt(mn) + ", " + fmt(mx) + "]" : std::string("no pixel counted")) + ", allowed [" + fmt(lo) + ", " +
               fmt(hi) + "]" + (finite ? "" : ", NaN/Inf present");
    if (std::string part = describe(a, c.args); !part.empty()) r.detail += "; " + part;
    return r;
}

// matches_pass: per pixel the largest channel difference against `tol`, on a `fraction` of the
// counted pixels, and/or the RMSE over them against `rmse`. Only `rmse` given: RMSE alone.
CheckResult matches(const image::Image& img, const image::Image& o, const graph::CheckDesc& c, const std::vector<int>& chans,
                    const Mask& mask) {
    CheckResult r;
    r.what = "matches_pass " + str(c.args, "other");
    if (img.width != o.width || img.height != o.height) {
        r.detail = "sizes differ: " + size_text(img) + " vs " + size_text(o);
        return r;
    }
    double tol = num(c.args, "tol", 1e-3);
    Agreement a = tally(img.pixels.size() / 4, mask, tol, [&](size_t i, double& sum_sq, size_t& values) {
        double e = 0;
        for (int ch : chans) {
            size_t k = i * 4 + static_cast<size_t>(ch);
            double d = std::fabs(double(img.pixels[k]) - double(o.pixels[k]));
            e = std::isfinite(d) ? std::max(e, d) : INFINITY;
            sum_sq += d * d;
            ++values;
        }
        return e;
    });
    const bool has_rmse = c.args.count("rmse") > 0;
    const bool per_pixel = !has_rmse || c.args.count("tol") || c.args.count("fraction");
    r.passed = a.counted > 0;
    if (per_pixel) r.passed = r.passed && a.fraction() >= num(c.args, "fraction", 1.0);
    if (has_rmse) r.passed = r.passed && a.rmse() <= num(c.args, "rmse", 0.0);
    r.detail = "max difference " + fmt(a.worst) + (per_pixel ? " (tol " + fmt(tol) + ")" : "");
    if (std::string part = describe(a, c.args); !part.empty()) r.detail += "; " + part;
    if (has_rmse || c.args.count("mask") || c.args.count("fraction"))
        r.detail += "; rmse " + fmt(a.rmse()) + (has_rmse ? " (bound " + fmt(num(c.args, "rmse", 0.0)) + ")" : "");
    if (a.counted == 0) r.detail += "; no pixel counted";
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
        // All four channels unless channel(s) name some.
        std::vector<int> which = c.args.count("channel") || c.args.count("channels") ? chans : std::vector<int>{0, 1, 2, 3};
        size_t bad = 0;
        for (size_t i = 0; i < n; ++i)
            for (int ch : which) bad += !std::isfinite(img.pixels[i * 4 + static_cast<size_t>(ch)]);
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
        auto mask = mask_of(c, img, other);
        if (!mask) {
            r.detail = mask.error().message;
            return r;
        }
        return range(img, c, chans, *mask, lo, hi);
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
        auto mask = o ? mask_of(c, img, other) : Result<Mask>(o.error());
        if (!mask) {
            r.detail = mask.error().message;
            return r;
        }
        return matches(img, **o, c, chans, *mask);
    }
    return std::nullopt;
}

} // namespace pl::check
