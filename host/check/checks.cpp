#include "check/checks.hpp"

#include "image/compare.hpp"
#include "image/image.hpp"
#include "vk/formats.hpp"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>

namespace fs = std::filesystem;

namespace pl::check {

namespace {

using graph::Value;

double num(const std::map<std::string, Value>& args, const std::string& k, double def) {
    auto it = args.find(k);
    if (it == args.end()) return def;
    if (auto d = std::get_if<double>(&it->second)) return *d;
    if (auto b = std::get_if<bool>(&it->second)) return *b ? 1.0 : 0.0;
    return def;
}

std::vector<double> vec(const std::map<std::string, Value>& args, const std::string& k) {
    auto it = args.find(k);
    if (it == args.end()) return {};
    if (auto v = std::get_if<std::vector<double>>(&it->second)) return *v;
    if (auto d = std::get_if<double>(&it->second)) return {*d};
    return {};
}

std::string str(const std::map<std::string, Value>& args, const std::string& k, const std::string& def = "") {
    auto it = args.find(k);
    if (it == args.end()) return def;
    if (auto s = std::get_if<std::string>(&it->second)) return *s;
    return def;
}

// Channels a check looks at: `channel = 0` or `channels = [0,1,2]`; default RGB.
std::vector<int> channels(const std::map<std::string, Value>& args) {
    std::vector<int> out;
    for (double c : vec(args, "channels")) out.push_back(static_cast<int>(c));
    if (args.count("channel")) out = {static_cast<int>(num(args, "channel", 0))};
    if (out.empty()) out = {0, 1, 2};
    return out;
}

std::string fmt(double v) {
    char b[32];
    std::snprintf(b, sizeof b, "%.6g", v);
    return b;
}

struct Images {
    exec::Executor& ex;
    std::map<std::string, image::Image> cache;
    Result<const image::Image*> get(const std::string& name) {
        auto it = cache.find(name);
        if (it != cache.end()) return &it->second;
        auto img = ex.read(name);
        if (!img) return img.error();
        return &cache.emplace(name, std::move(img.value())).first->second;
    }
};

CheckResult probe(const image::Image& img, const graph::CheckDesc& c) {
    CheckResult r;
    auto uv = vec(c.args, "uv"), px = vec(c.args, "px"), expect = vec(c.args, "expect");
    double tol = num(c.args, "tol", 0.01);
    int x = 0, y = 0;
    if (uv.size() == 2) {
        // Texel centres: uv (0.5/w, 0.5/h) is texel (0,0).
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
    const float* p = img.at(x, y);
    double worst = 0.0;
    std::string got;
    for (size_t k = 0; k < expect.size(); ++k) {
        worst = std::max(worst, std::fabs(p[k] - expect[k]));
        got += (k ? "," : "") + fmt(p[k]);
    }
    r.passed = worst <= tol;
    r.detail = "got (" + got + "), max error " + fmt(worst) + " (tol " + fmt(tol) + ")";
    return r;
}

CheckResult property(const image::Image& img, const graph::CheckDesc& c, Images& images) {
    CheckResult r;
    r.what = c.kind;
    auto chans = channels(c.args);
    size_t n = static_cast<size_t>(img.width) * img.height;
    if (c.kind == "no_nan") {
        size_t bad = 0;
        for (float v : img.pixels) bad += !std::isfinite(v);
        r.passed = bad == 0;
        r.detail = std::to_string(bad) + " NaN/Inf value(s)";
        return r;
    }
    if (c.kind == "range") {
        double lo = num(c.args, "min", 0.0), hi = num(c.args, "max", 1.0);
        double mn = INFINITY, mx = -INFINITY;
        for (size_t i = 0; i < n; ++i)
            for (int ch : chans) {
                double v = img.pixels[i * 4 + static_cast<size_t>(ch)];
                mn = std::min(mn, v);
                mx = std::max(mx, v);
            }
        r.passed = mn >= lo && mx <= hi;
        r.detail = "values in [" + fmt(mn) + ", " + fmt(mx) + "], allowed [" + fmt(lo) + ", " + fmt(hi) + "]";
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
    if (c.kind == "matches_pass") {
        std::string other = str(c.args, "other");
        auto o = images.get(other);
        if (!o) {
            r.detail = o.error().message;
            return r;
        }
        const image::Image& b = **o;
        if (b.width != img.width || b.height != img.height) {
            r.detail = "sizes differ";
            return r;
        }
        double worst = 0.0;
        for (size_t i = 0; i < n; ++i)
            for (int ch : chans) {
                size_t k = i * 4 + static_cast<size_t>(ch);
                worst = std::max(worst, static_cast<double>(std::fabs(img.pixels[k] - b.pixels[k])));
            }
        double tol = num(c.args, "tol", 1e-3);
        r.what = "matches_pass " + other;
        r.passed = worst <= tol;
        r.detail = "max difference " + fmt(worst) + " (tol " + fmt(tol) + ")";
        return r;
    }
    r.detail = "unknown check kind '" + c.kind + "' (known: probe, no_nan, range, mean, matches_pass)";
    return r;
}

CheckResult golden(const image::Image& img, const graph::TestDesc& t, const fs::path& dir, const RunOptions& opt,
                   const std::string& case_id) {
    CheckResult r;
    fs::path file = dir / t.golden;
    r.what = "golden " + t.golden;
    std::error_code ec;
    bool exists = fs::exists(file, ec);
    bool update = opt.update && (opt.update_only.empty() || opt.update_only == t.name);
    if (!exists || update) {
        if (!exists && opt.ci) {
            r.detail = "golden missing (CI never writes goldens; run `passlab test --update` locally)";
            return r;
        }
        fs::create_directories(file.parent_path(), ec);
        if (auto s = image::save_image(img, file, {.exr_half = false, .png_compression = 6}); !s) {
            r.detail = s.error().message;
            return r;
        }
        r.passed = true;
        r.detail = exists ? "golden rewritten" : "golden written (it did not exist)";
        return r;
    }
    auto expected = image::load_image(file);
    if (!expected) {
        r.detail = expected.error().message;
        return r;
    }
    if (expected->width != img.width || expected->height != img.height) {
        r.detail = "golden is " + std::to_string(expected->width) + "x" + std::to_string(expected->height) +
                   ", render is " + std::to_string(img.width) + "x" + std::to_string(img.height);
        return r;
    }
    auto tol = [&](const char* k, double def) {
        auto it = t.tolerance.find(k);
        return it == t.tolerance.end() ? def : it->second;
    };
    // Defaults: 8-bit goldens differ by driver rounding of 1/255 at most; 0.02 absolute catches
    // a real change, and 0.1% of pixels may differ on edges.
    double threshold = tol("bad_threshold", 0.02);
    image::DiffStats d = image::diff(img, *expected, static_cast<float>(threshold));
    double max_rmse = tol("rmse", 0.01), max_bad = tol("max_bad_fraction", 0.001), max_abs = tol("max_abs", 1.0);
    r.passed = d.rmse <= max_rmse && d.bad_fraction <= max_bad && d.max_abs <= max_abs;
    r.detail = "rmse " + fmt(d.rmse) + " (≤ " + fmt(max_rmse) + "), bad " + fmt(d.bad_fraction) + " (≤ " +
               fmt(max_bad) + " over " + fmt(threshold) + "), max " + fmt(d.max_abs) + " (≤ " + fmt(max_abs) + ")";
    if (!r.passed && !opt.fail_dir.empty()) {
        fs::create_directories(opt.fail_dir, ec);
        std::string ext = file.extension().string();
        (void)image::save_image(img, opt.fail_dir / (case_id + ".actual" + ext));
        (void)image::save_image(*expected, opt.fail_dir / (case_id + ".expected" + ext));
        (void)image::save_image(image::diff_heatmap(img, *expected), opt.fail_dir / (case_id + ".diff.png"));
        r.detail += "; images in " + opt.fail_dir.string();
    }
    return r;
}

} // namespace

std::vector<CaseResult> run_preset_tests(vk::Context& ctx, const fs::path& toml, const RunOptions& opt) {
    std::vector<CaseResult> out;
    exec::BuildOptions base;
    base.cache_dir = opt.cache_dir;
    // Parse once to learn the cases; each case is then built with its own size and params.
    auto probe_build = exec::build_graph(toml, base);
    std::string preset = toml.parent_path().filename().string();
    if (!probe_build) {
        CaseResult cr;
        cr.preset = preset;
        cr.name = "(build)";
        cr.error = probe_build.error().format();
        out.push_back(cr);
        return out;
    }
    const graph::GraphDesc& desc = probe_build->desc;
    for (const auto& t : desc.tests) {
        if (ctx.hung()) break;  // a runaway shader still occupies the device
        auto t0 = std::chrono::steady_clock::now();
        CaseResult cr;
        cr.preset = preset;
        cr.name = t.name;
        size_t msgs_before = ctx.validation_message_count();
        for (const auto& f : t.requires_features)
            if (!ctx.features().has(f)) {
                cr.skipped = true;
                cr.skip_reason = "device lacks " + f;
            }
        if (cr.skipped) {
            out.push_back(cr);
            continue;
        }
        exec::BuildOptions bo = base;
        if (t.size) bo.size = *t.size;
        bo.set_values = t.set;
        auto built = exec::build_graph(toml, bo);
        if (!built) {
            cr.error = built.error().format();
            out.push_back(cr);
            continue;
        }
        std::string output = built->desc.output;
        auto ex = exec::Executor::create(ctx, std::move(built.value()));
        if (!ex) {
            cr.error = ex.error().format();
            out.push_back(cr);
            continue;
        }
        bool ok = true;
        for (int f = 0; f < t.frames && ok; ++f) {
            exec::FrameInput in;
            in.index = f;
            in.delta = t.step;
            in.time = t.time - static_cast<double>(t.frames - 1 - f) * t.step;
            in.camera = t.camera;
            if (auto s = (*ex)->render(in); !s) {
                cr.error = s.error().format();
                ok = false;
            }
        }
        if (ok) {
            Images images{**ex, {}};
            std::string subject = t.pass.empty() ? output : t.pass;
            auto img = images.get(subject);
            if (!img) {
                cr.error = img.error().format();
            } else {
                if (!t.golden.empty())
                    cr.checks.push_back(golden(**img, t, toml.parent_path(), opt, preset + "." + t.name));
                for (const auto& c : t.checks) {
                    std::string which = str(c.args, "pass", subject);
                    auto target = images.get(which);
                    if (!target) {
                        cr.checks.push_back({c.kind, false, target.error().message});
                        continue;
                    }
                    cr.checks.push_back(c.kind == "probe" ? probe(**target, c) : property(**target, c, images));
                }
            }
        }
        auto msgs = ctx.validation_messages();
        for (size_t k = msgs_before; k < msgs.size(); ++k) cr.validation.push_back(msgs[k]);
        cr.passed = cr.error.empty() && cr.validation.empty();
        for (const auto& c : cr.checks) cr.passed = cr.passed && c.passed;
        cr.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        out.push_back(cr);
    }
    return out;
}

} // namespace pl::check
