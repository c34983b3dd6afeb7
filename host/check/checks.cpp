// The case runner: builds and renders a [[test]] case with a paused, fixed-step clock, then
// evaluates its golden and checks. Checks that need other renders (stable, order_independent,
// monotone) re-render the case with one thing changed.
#include "check/checks.hpp"

#include "check/args.hpp"
#include "check/buffer_checks.hpp"
#include "check/golden.hpp"
#include "check/properties.hpp"
#include "exec/bind.hpp"
#include "image/image.hpp"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <map>
#include <tuple>

namespace fs = std::filesystem;

namespace pl::check {

namespace {

struct Rendered {
    std::unique_ptr<exec::Executor> ex;
    std::map<std::tuple<std::string, int, int>, image::Image> cache;
    std::map<std::string, std::vector<uint32_t>> buffers;
    // One level and layer of an image (tests read any mip/layer: `mip = 3`, `layer = 2`).
    Result<const image::Image*> get(const std::string& name, int mip = 0, int layer = 0) {
        auto key = std::make_tuple(name, mip, layer);
        auto it = cache.find(key);
        if (it != cache.end()) return &it->second;
        auto img = ex->read(name, mip, layer);
        if (!img) return img.error();
        return &cache.emplace(key, std::move(img.value())).first->second;
    }
    Result<const std::vector<uint32_t>*> get_buffer(const std::string& name) {
        auto it = buffers.find(name);
        if (it != buffers.end()) return &it->second;
        auto words = ex->read_buffer(name);
        if (!words) return words.error();
        return &buffers.emplace(name, std::move(words.value())).first->second;
    }
};

// One result per declared counter: a count above the capacity after any frame fails the case.
CheckResult counter_result(const exec::CounterReading& c) {
    CheckResult r;
    r.what = "counter buffer '" + c.buffer + "' <= capacity " + std::to_string(c.capacity);
    r.passed = c.overflow_frame < 0;
    r.detail = r.passed ? "largest count " + std::to_string(c.peak) + " (after frame " + std::to_string(c.peak_frame) + ")"
                        : exec::overflow_message(c) + " (largest count " + std::to_string(c.peak) + ")";
    return r;
}

// A `reduction` buffer check: the image it reduces (`of`) and its `mask`, read from the same run.
CheckResult reduction_check(Rendered& rendered, const std::vector<uint32_t>& words, const graph::CheckDesc& c) {
    auto fail = [&](const std::string& why) { return CheckResult{c.kind, false, why, {}, {}, {}}; };
    auto of = rendered.get(str(c.args, "of"));
    if (!of) return fail(of.error().message);
    Mask mask;
    if (c.args.count("mask")) {
        auto m = rendered.get(str(c.args, "mask"));
        if (!m) return fail(m.error().message);
        if ((*m)->width != (*of)->width || (*m)->height != (*of)->height)
            return fail("mask '" + str(c.args, "mask") + "' is " + std::to_string((*m)->width) + "x" + std::to_string((*m)->height) + ", image '" +
                        str(c.args, "of") + "' " + std::to_string((*of)->width) + "x" + std::to_string((*of)->height));
        mask.img = *m;
        mask.channel = static_cast<int>(num(c.args, "mask_channel", 0));
        mask.invert = num(c.args, "invert_mask", 0) != 0;
    }
    return buffer_reduction(words, c, **of, mask);
}

struct Variant {
    std::map<std::string, graph::Value> set;  // extra param overrides
    exec::InstanceOrder order = exec::InstanceOrder::natural;
};

Result<Rendered> render_case(vk::Context& ctx, const fs::path& toml, const graph::TestDesc& t, const RunOptions& opt,
                             const Variant& v = {}) {
    if (ctx.hung()) return make_error("not rendered: an earlier render of this case ran away");
    exec::BuildOptions bo;
    bo.cache_dir = opt.cache_dir;
    bo.overlay_dirs = opt.overlay_dirs;
    if (t.size) bo.size = *t.size;
    bo.set_values = t.set;
    bo.cameras = t.cameras;
    for (const auto& [k, val] : v.set) bo.set_values[k] = val;
    auto built = exec::build_graph(toml, bo);
    if (!built) return built.error();
    auto ex = exec::Executor::create(ctx, std::move(built.value()));
    if (!ex) return ex.error();
    (*ex)->set_timeout(opt.timeout);
    Rendered out{std::move(ex.value()), {}, {}};
    for (int f = 0; f < t.frames; ++f) {
        exec::FrameInput in;
        in.index = f;
        in.delta = t.step;
        in.time = t.time - static_cast<double>(t.frames - 1 - f) * t.step;
        in.camera = t.camera;
        in.mouse = glm::vec4(float(t.mouse[0]), float(t.mouse[1]), float(t.mouse[2]), float(t.mouse[3]));
        in.keys = exec::held_keys(t.held_keys, f);
        in.instance_order = v.order;
        if (auto s = out.ex->render(in); !s) return s.error();
    }
    return out;
}

// Checks that compare the case against other renders of it.
std::optional<CheckResult> render_property(vk::Context& ctx, const fs::path& toml, const graph::TestDesc& t,
                                           const RunOptions& opt, const graph::CheckDesc& c, const std::string& subject,
                                           const image::Image& img) {
    CheckResult r;
    r.what = c.kind;
    auto chans = channels(c.args);
    auto compare_with = [&](const Variant& v, const std::string& label, double tol) {
        auto other = render_case(ctx, toml, t, opt, v);
        if (!other) {
            r.detail = label + ": " + other.error().message;
            return false;
        }
        auto o = other->get(subject, t.mip, t.layer);
        if (!o) {
            r.detail = label + ": " + o.error().message;
            return false;
        }
        double d = max_difference(img, **o, chans);
        r.detail += (r.detail.empty() ? "" : "; ") + label + " max difference " + fmt(d) + " (tol " + fmt(tol) + ")";
        return d <= tol;
    };
    if (c.kind == "stable") {
        // The same case rendered again must agree: catches uninitialised reads and races.
        r.passed = compare_with({}, "second render", num(c.args, "tol", 0.0));
        return r;
    }
    if (c.kind == "order_independent") {
        double tol = num(c.args, "tol", 1e-3);
        bool a = compare_with({{}, exec::InstanceOrder::reversed}, "reversed instances", tol);
        bool b = compare_with({{}, exec::InstanceOrder::shuffled}, "shuffled instances", tol);
        r.passed = a && b;
        return r;
    }
    if (c.kind == "matches_variant") {
        // The case equals itself with one param changed (e.g. a noise amplitude of 0 must give
        // the noiseless technique, a parallax height of 0 plain normal mapping).
        std::string param = str(c.args, "param");
        r.what = "matches_variant " + param;
        auto it = c.args.find("value");
        if (param.empty() || it == c.args.end()) {
            r.detail = "needs param = \"name\" and value = ...";
            return r;
        }
        Variant v;
        v.set[param] = it->second;
        r.passed = compare_with(v, param + " changed", num(c.args, "tol", 1e-3));
        return r;
    }
    if (c.kind == "monotone") {
        // The mean of the subject over a sweep of one param moves in one direction.
        std::string param = str(c.args, "param");
        auto values = vec(c.args, "values");
        std::string dir = str(c.args, "direction", "increasing");
        double tol = num(c.args, "tol", 0.0);
        r.what = "monotone " + param;
        if (param.empty() || values.size() < 2) {
            r.detail = "needs param = \"name\" and values = [at least 2 numbers]";
            return r;
        }
        std::vector<double> means;
        for (double v : values) {
            Variant var;
            var.set[param] = v;
            auto other = render_case(ctx, toml, t, opt, var);
            if (!other) {
                r.detail = other.error().message;
                return r;
            }
            auto o = other->get(subject, t.mip, t.layer);
            if (!o) {
                r.detail = o.error().message;
                return r;
            }
            double sum = 0;
            size_t n = static_cast<size_t>((*o)->width) * (*o)->height;
            for (size_t i = 0; i < n; ++i)
                for (int ch : chans) sum += (*o)->pixels[i * 4 + static_cast<size_t>(ch)];
            means.push_back(sum / double(n * chans.size()));
        }
        // A NaN or Inf mean compares false both ways, so it would pass any direction: fail it.
        r.passed = std::all_of(means.begin(), means.end(), [](double m) { return std::isfinite(m); });
        for (size_t i = 1; i < means.size(); ++i) {
            double step = means[i] - means[i - 1];
            if (dir == "decreasing" ? step > tol : step < -tol) r.passed = false;
        }
        r.detail = "means";
        for (size_t i = 0; i < means.size(); ++i) r.detail += (i ? ", " : " ") + fmt(means[i]);
        r.detail += " (" + dir + ")";
        return r;
    }
    (void)img;
    return std::nullopt;
}

} // namespace

// The image a failed check read, for the report: DIR/<case>.check-N.png, tone-mapped when it
// holds values outside [0, 1] (then the name says so). Empty when the case image shows it
// already (`same_as_case` and in range) or it cannot be written (the check's failure stands).
std::string save_check_image(const image::Image& img, const fs::path& case_path, size_t index, bool same_as_case) {
    bool tone_mapped = false;
    image::Image shown = image::display_copy(img, &tone_mapped);
    if (same_as_case && !tone_mapped) return {};
    if (shown.depth > 1) {  // a 3D image: its first slice
        shown.depth = 1;
        shown.pixels.resize(static_cast<size_t>(shown.width) * shown.height * 4);
    }
    fs::path f = case_path;
    f += ".check-" + std::to_string(index) + (tone_mapped ? ".tonemapped.png" : ".png");
    std::error_code ec;
    fs::create_directories(f.parent_path(), ec);
    return image::save_image(shown, f) ? f.string() : std::string();
}

fs::path case_stem(const RunOptions& opt, const fs::path& toml, const std::string& name) {
    if (opt.output_stem.empty()) return toml.parent_path().filename().string() + "." + name;
    return opt.output_stem / name;
}

std::vector<CaseResult> run_preset_tests(vk::ContextSlot& slot, const fs::path& toml, const RunOptions& opt) {
    std::vector<CaseResult> out;
    exec::BuildOptions base;
    base.cache_dir = opt.cache_dir;
    base.overlay_dirs = opt.overlay_dirs;
    // Build once to learn the cases (and report a broken preset once); each case builds again
    // with its own size and params.
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
        if (opt.cases && !opt.cases->count(t.name)) continue;
        auto t0 = std::chrono::steady_clock::now();
        CaseResult cr;
        cr.preset = preset;
        cr.name = t.name;
        cr.hint = t.hint;
        cr.weight = t.weight;
        cr.visibility = t.visibility;
        auto device = slot.get();  // a fresh one after a runaway case
        if (!device) {
            cr.error = device.error().format();
            out.push_back(cr);
            continue;
        }
        vk::Context& ctx = **device;
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
        auto rendered = render_case(ctx, toml, t, opt);
        if (!rendered) {
            cr.error = rendered.error().format();
        } else {
            std::string subject = t.pass.empty() ? rendered->ex->graph().desc.output : t.pass;
            auto img = rendered->get(subject, t.mip, t.layer);
            if (!img) {
                cr.error = img.error().format();
            } else {
                const fs::path case_id = case_stem(opt, toml, t.name);
                if (!opt.report_dir.empty()) {
                    fs::path f = opt.report_dir / case_id;
                    f += ".png";
                    std::error_code ec;
                    fs::create_directories(f.parent_path(), ec);
                    if (auto s = image::save_image(**img, f); s) cr.image_file = f.string();
                    else cr.error += "cannot write " + f.string() + ": " + s.error().message + "\n";
                }
                if (!t.golden.empty())
                    cr.checks.push_back(compare_golden(**img, t, toml.parent_path(), opt, case_id));
                for (const auto& w : rendered->ex->counters()) cr.checks.push_back(counter_result(w));
                for (const auto& c : t.checks) {
                    if (ctx.hung()) break;  // a check's own render ran away: nothing more to read
                    if (c.args.count("buffer")) {
                        auto words = rendered->get_buffer(str(c.args, "buffer"));
                        const auto& cg = rendered->ex->graph();
                        if (!words) cr.checks.push_back({c.kind, false, words.error().message, {}, {}, {}});
                        else if (c.kind == "reduction") cr.checks.push_back(reduction_check(*rendered, **words, c));
                        else cr.checks.push_back(buffer_property(**words, c, exec::size_env(cg.desc, cg.view)));
                        continue;
                    }
                    std::string which = str(c.args, "pass", subject);
                    // A check on the case's own image defaults to the case's level and layer.
                    bool own = which == subject;
                    auto target = rendered->get(which, static_cast<int>(num(c.args, "mip", own ? t.mip : 0)),
                                                static_cast<int>(num(c.args, "layer", own ? t.layer : 0)));
                    if (!target) {
                        cr.checks.push_back({c.kind, false, target.error().message, {}, {}, {}});
                        continue;
                    }
                    ImageLookup lookup = [&](const std::string& n) { return rendered->get(n); };
                    if (auto r = image_property(**target, c, lookup)) cr.checks.push_back(*r);
                    else if (auto r2 = render_property(ctx, toml, t, opt, c, which, **target)) cr.checks.push_back(*r2);
                    else
                        cr.checks.push_back({c.kind, false, "no image check of kind '" + c.kind + "' (" + c.loc.str() + ")", {}, {}, {}});
                    // A failed check shows, in the report, the image it read, unless that is the
                    // case's own 8-bit image already there.
                    if (!opt.report_dir.empty() && !cr.checks.back().passed) {
                        const bool same_image = own && num(c.args, "mip", t.mip) == t.mip && num(c.args, "layer", t.layer) == t.layer;
                        cr.checks.back().actual_file = save_check_image(**target, opt.report_dir / case_id, cr.checks.size(),
                                                                        same_image && (**target).depth == 1 && !cr.image_file.empty());
                    }
                }
            }
        }
        if (ctx.hung())
            cr.error += "    the device is left to the runaway shader; the remaining cases run on a fresh one\n";
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
