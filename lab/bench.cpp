// `passlab bench PRESET`: frame timings of a preset on this device. Wall time per frame covers
// record + submit + fence wait (the CPU's view); per-pass GPU times come from timestamps.
// Figures, not verdicts: nothing here fails on a time.
#include "verbs.hpp"

#include "exec/build.hpp"
#include "exec/executor.hpp"
#include "vk/context.hpp"

#include <nlohmann/json.hpp>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <map>

namespace pl::lab {

namespace {

double percentile(std::vector<double> v, double p) {
    if (v.empty()) return 0;
    std::sort(v.begin(), v.end());
    size_t i = static_cast<size_t>(p * double(v.size() - 1) + 0.5);
    return v[std::min(i, v.size() - 1)];
}

double peak_rss_mb() {
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_maxrss) / 1024.0;  // Linux reports KiB
}

} // namespace

int bench(const BenchOptions& o, const CommonOptions& c) {
    if (!o.json.empty())
        if (auto s = check_output_file(o.json, "--json"); !s) return report(s.error());
    auto lp = resolve_and_configure(o.preset, o.size, o.set, c);
    if (!lp) return report(lp.error());
    const auto toml = &lp->toml;
    exec::BuildOptions& bo = lp->options;
    auto built = exec::build_graph(*toml, bo);
    if (!built) return report(built.error());
    vk::ContextOptions co;
    co.device = c.device;
    co.validation = c.validation;  // off by default: the layer costs CPU time
    auto ctx = vk::Context::create(co);
    if (!ctx) return report(ctx.error());
    auto view = built->view;
    auto ex = exec::Executor::create(**ctx, std::move(built.value()));
    if (!ex) return report(ex.error());
    (*ex)->set_timeout(timeout(c));

    std::vector<double> frame_ms, record_ms;
    std::map<std::string, std::vector<double>> pass_ms;
    std::vector<std::string> pass_order;
    // Two rounds: frame times without timestamps (lavapipe drains its queue to write one), then
    // per-pass GPU times with them.
    for (int f = 0; f < o.warmup + 2 * o.frames; ++f) {
        bool timing_round = f >= o.warmup + o.frames;
        (*ex)->set_timestamps(timing_round);
        exec::FrameInput in;
        in.index = f;
        in.time = f / 60.0;
        auto t0 = std::chrono::steady_clock::now();
        if (auto s = (*ex)->render(in); !s) {
            int rc = report(s.error());
            if ((*ctx)->hung()) exit_after_hang(rc);
            return rc;
        }
        double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
        if (f < o.warmup) continue;  // first frames include llvmpipe's pipeline compilation
        if (!timing_round) {
            frame_ms.push_back(ms);
            record_ms.push_back((*ex)->record_ms());
            continue;
        }
        for (const auto& t : (*ex)->timings()) {
            if (!pass_ms.count(t.name)) pass_order.push_back(t.name);
            pass_ms[t.name].push_back(t.gpu_ms);
        }
    }
    double mn = *std::min_element(frame_ms.begin(), frame_ms.end());
    double med = percentile(frame_ms, 0.5), p95 = percentile(frame_ms, 0.95), rss = peak_rss_mb();
    std::string device = (*ctx)->device_description();
    std::printf("preset  %s\nsize    %dx%d, %d frames after %d warm-up\ndevice  %s\n", toml->string().c_str(), view[0],
                view[1], o.frames, o.warmup, device.c_str());
    std::printf("frame   min %.3f ms, median %.3f ms, p95 %.3f ms (record + submit + wait)\n", mn, med, p95);
    double rec_med = percentile(record_ms, 0.5), rec_p95 = percentile(record_ms, 0.95);
    std::printf("record  median %.3f ms, p95 %.3f ms (CPU: blocks, descriptors, commands; the host's own cost)\n", rec_med, rec_p95);
    std::printf("memory  peak RSS %.1f MB\n", rss);
    for (const auto& [name, m] : (*ex)->resources().meshes)  // host cost paid once, at creation
        if (m.simplified)
            std::printf("mesh    %s: simplified %zu -> %zu triangles%s in %.2f ms (%zu collapses, max error %.3g)\n",
                        name.c_str(), m.simplified->input_triangles, m.simplified->output_triangles,
                        m.has_morph ? (", morph target " + std::to_string(m.simplified->morph_triangles)).c_str() : "",
                        m.simplify_ms, m.simplified->collapses, m.simplified->max_error);
    std::printf("%-24s %12s %12s\n", "pass", "median GPU", "p95 GPU");
    for (const auto& n : pass_order)
        std::printf("%-24s %9.3f ms %9.3f ms\n", n.c_str(), percentile(pass_ms[n], 0.5), percentile(pass_ms[n], 0.95));
    if (!o.json.empty()) {
        nlohmann::ordered_json passes = nlohmann::ordered_json::array();
        for (const auto& n : pass_order)
            passes.push_back({{"name", n}, {"gpu_ms_median", percentile(pass_ms[n], 0.5)}, {"gpu_ms_p95", percentile(pass_ms[n], 0.95)}});
        nlohmann::ordered_json j = {{"preset", toml->string()},
                            {"width", view[0]},
                            {"height", view[1]},
                            {"frames", o.frames},
                            {"warmup", o.warmup},
                            {"device", device},
                            {"frame_ms", {{"min", mn}, {"median", med}, {"p95", p95}}},
                            {"record_ms", {{"median", rec_med}, {"p95", rec_p95}}},
                            {"peak_rss_mb", rss},
                            {"passes", passes}};
        std::ofstream out(o.json, std::ios::trunc);
        out << j.dump(2) << "\n";
        out.close();
        if (!out) {
            Error e = make_error("bench: cannot write " + o.json);
            e.code = ExitCode::environment;
            return report(e);
        }
        std::printf("json    %s\n", o.json.c_str());
    }
    return 0;
}

} // namespace pl::lab
