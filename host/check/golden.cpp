#include "check/golden.hpp"

#include "check/args.hpp"
#include "image/compare.hpp"

namespace fs = std::filesystem;

namespace pl::check {

CheckResult compare_golden(const image::Image& img, const graph::TestDesc& t, const fs::path& dir, const RunOptions& opt,
                           const fs::path& case_id) {
    CheckResult r;
    fs::path file = dir / t.golden;
    r.what = "golden " + t.golden;
    std::error_code ec;
    bool exists = fs::exists(file, ec);
    bool update = opt.update;  // --case selects which cases run, so which goldens --update rewrites
    auto tol = [&](const char* k, double def) {
        auto it = t.tolerance.find(k);
        return it == t.tolerance.end() ? def : it->second;
    };
    std::optional<image::Image> previous;
    std::string unreadable;  // why an existing golden cannot be read (a FIFO, a device, corrupt)
    if (exists) {
        auto prev = image::load_image(file);
        if (prev) previous = std::move(prev.value());
        else unreadable = prev.error().message;
    }
    if (!exists || update) {
        if (!exists && opt.ci) {
            r.detail = "golden missing (CI never writes goldens; run `passlab test --update` locally and look at it)";
            return r;
        }
        fs::create_directories(file.parent_path(), ec);
        // Goldens are committed: zlib level 6 keeps them small; they are written rarely.
        if (auto s = image::save_image(img, file, {.exr_half = false, .png_compression = 6}); !s) {
            r.detail = s.error().message;
            return r;
        }
        r.passed = true;
        r.golden_write = exists ? CheckResult::GoldenWrite::rewritten : CheckResult::GoldenWrite::written;
        if (previous && previous->width == img.width && previous->height == img.height) {
            image::DiffStats d = image::diff(img, *previous, static_cast<float>(tol("bad_threshold", 0.02)));
            r.detail = "golden rewritten; changed by rmse " + fmt(d.rmse) + ", max " + fmt(d.max_abs) +
                       ", bad fraction " + fmt(d.bad_fraction);
        } else {
            r.detail = exists ? "golden rewritten (size changed)" : "golden written (it did not exist): look at " + file.string();
        }
        r.expected_file = file.string();
        return r;
    }
    if (!previous) {
        r.detail = unreadable.empty() ? "cannot read golden " + file.string() : unreadable;
        return r;
    }
    const image::Image& expected = *previous;
    r.expected_file = file.string();
    if (expected.width != img.width || expected.height != img.height) {
        r.detail = "golden is " + std::to_string(expected.width) + "x" + std::to_string(expected.height) + ", render is " +
                   std::to_string(img.width) + "x" + std::to_string(img.height);
        return r;
    }
    // Defaults: 8-bit goldens differ between drivers by a rounding step (1/255); 0.02 absolute
    // still catches a real change, and 0.1% of pixels (edges) may move.
    double threshold = tol("bad_threshold", 0.02);
    image::DiffStats d = image::diff(img, expected, static_cast<float>(threshold));
    double max_rmse = tol("rmse", 0.01), max_bad = tol("max_bad_fraction", 0.001), max_abs = tol("max_abs", 1.0);
    r.passed = d.rmse <= max_rmse && d.bad_fraction <= max_bad && d.max_abs <= max_abs;
    r.detail = "rmse " + fmt(d.rmse) + " (≤ " + fmt(max_rmse) + "), bad " + fmt(d.bad_fraction) + " (≤ " + fmt(max_bad) +
               " over " + fmt(threshold) + "), max " + fmt(d.max_abs) + " (≤ " + fmt(max_abs) + ")";
    if (t.tolerance.count("ssim")) {
        // SSIM (structure, 8x8 windows) catches a shifted pattern that RMSE may forgive.
        double s = image::ssim(img, expected), min_ssim = tol("ssim", 0.98);
        r.passed = r.passed && s >= min_ssim;
        r.detail += ", ssim " + fmt(s) + " (≥ " + fmt(min_ssim) + ")";
    }
    if ((!r.passed || !opt.report_dir.empty()) && !opt.fail_dir.empty()) {
        const fs::path out = r.passed ? opt.report_dir : opt.fail_dir;
        const fs::path stem = out / case_id;
        fs::create_directories(stem.parent_path(), ec);
        const std::string ext = file.extension().string();
        auto named = [&](const std::string& suffix) { return stem.string() + suffix; };
        // actual, expected (a copy of the golden, so the folder alone tells the story) and diff.
        std::string why;
        if (auto s = image::save_image(img, named(".actual" + ext)); s) r.actual_file = named(".actual" + ext);
        else why = s.error().message;
        fs::copy_file(file, named(".expected" + ext), fs::copy_options::overwrite_existing, ec);
        if (!ec) r.expected_file = named(".expected" + ext);
        else why = "cannot copy the golden to " + named(".expected" + ext) + ": " + ec.message();
        if (auto s = image::save_image(image::diff_heatmap(img, expected), named(".diff.png")); s) r.diff_file = named(".diff.png");
        else why = s.error().message;
        if (!why.empty()) {
            r.passed = false;
            r.detail += "; cannot write the images into " + out.string() + ": " + why;
        } else if (!r.passed) {
            r.detail += "; actual, expected and diff in " + stem.parent_path().string();
        }
    }
    return r;
}

} // namespace pl::check
