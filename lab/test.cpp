// `passlab test`: runs the [[test]] cases of presets headlessly under the validation layer and
// prints one line per case and a closing summary. Exit 1 if any case fails.
#include "verbs.hpp"
#include "sources.hpp"

#include "check/checks.hpp"
#include "report.hpp"
#include "exec/build.hpp"
#include "vk/context.hpp"

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

namespace fs = std::filesystem;

namespace pl::lab {


int test(const TestOptions& o, const CommonOptions& c) {
    std::vector<std::string> args = o.targets;
    if (args.empty()) args = {exec::presets_dir().string(), (exec::presets_dir().parent_path() / "tests" / "graphs").string()};
    std::vector<fs::path> presets;
    for (const auto& a : args) {
        auto found = collect_presets(a);
        if (!found) return report(found.error());
        presets.insert(presets.end(), found->begin(), found->end());
    }

    vk::ContextOptions co;
    // Tests always run under the validation layer when it is installed (--no-validation to skip).
    co.validation = !o.no_validation;
    co.device = c.device;
    auto ctx = vk::Context::create(co);
    if (!ctx) return report(ctx.error());
    if (!(*ctx)->validation_enabled() && !o.no_validation)
        std::fprintf(stderr, "test: the Khronos validation layer is not installed; running without it\n");

    check::RunOptions ro;
    const char* ci_env = std::getenv("CI");
    ro.ci = o.ci || (ci_env && std::string(ci_env) == "true");
    ro.update = o.update;
    ro.update_only = o.update_case;
    ro.cache_dir = cache_dir(c);
    ro.fail_dir = o.fail_dir;
    ro.report_dir = o.report_dir;
    auto overlay = exercise_overlay(c);
    if (!overlay) return report(overlay.error());
    ro.overlay_dirs = *overlay;
    // An exercise copy is the student's: its renders must never become goldens.
    if (!ro.overlay_dirs.empty()) ro.ci = true, ro.update = false;
    auto t0 = std::chrono::steady_clock::now();
    std::vector<ReportEntry> entries;

    int passed = 0, failed = 0, skipped = 0;
    for (const auto& p : presets) {
        auto results = check::run_preset_tests(**ctx, p, ro);
        std::string where = fs::proximate(p.parent_path()).string();
        for (const auto& r : results) entries.push_back({where, r});
        for (const auto& r : results) {
            if (r.skipped) {
                ++skipped;
                std::printf("SKIP %s: %s (%s)\n", where.c_str(), r.name.c_str(), r.skip_reason.c_str());
                continue;
            }
            (r.passed ? passed : failed)++;
            std::printf("%s %s: %s (%.0f ms)\n", r.passed ? "PASS" : "FAIL", where.c_str(), r.name.c_str(), r.ms);
            if (!r.error.empty()) std::printf("%s", map_scratch_text(r.error).c_str());
            for (const auto& ch : r.checks)
                if (!ch.passed || o.verbose)
                    std::printf("    %s %s: %s\n", ch.passed ? "ok  " : "FAIL", ch.what.c_str(), ch.detail.c_str());
            for (const auto& v : r.validation) std::printf("    validation: %s\n", v.c_str());
        }
        if ((*ctx)->hung()) {
            std::printf("stopping: the GPU is still running a shader that exceeded the time limit\n");
            std::printf("%d passed, %d failed\n", passed, failed + 1);
            exit_after_hang(1);
        }
    }
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!o.report_dir.empty()) {
        write_report(o.report_dir, entries, (*ctx)->device_description(), ms);
        std::printf("report: %s\n", (fs::path(o.report_dir) / "index.html").string().c_str());
    }
    std::printf("%d passed, %d failed", passed, failed);
    if (skipped) std::printf(", %d skipped", skipped);
    std::printf(" (%s)\n", (*ctx)->device_description().c_str());
    return failed ? 1 : 0;
}

} // namespace pl::lab
