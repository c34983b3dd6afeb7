// `passlab test`: runs the [[test]] cases of presets headlessly under the validation layer and
// prints one line per case and a closing summary naming the failed cases. Exit 1 if any case
// fails or nothing was selected. Selection (--case, shards) is test_select.cpp, -j workers
// test_workers.cpp, --json/--junit results.cpp.
#include "verbs.hpp"
#include "sources.hpp"

#include "check/checks.hpp"
#include "report.hpp"
#include "results.hpp"
#include "test_select.hpp"
#include "test_workers.hpp"
#include "vk/context_slot.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>

#include <csignal>
#include <sys/prctl.h>

namespace fs = std::filesystem;

namespace pl::lab {

namespace {

void print_case(const ReportEntry& e, bool verbose) {
    const auto& r = e.result;
    if (r.skipped) {
        std::printf("SKIP %s: %s (%s)\n", e.where.c_str(), r.name.c_str(), r.skip_reason.c_str());
        return;
    }
    std::printf("%s %s: %s (%.0f ms)\n", r.passed ? "PASS" : "FAIL", e.where.c_str(), r.name.c_str(), r.ms);
    if (!r.error.empty()) std::printf("%s", map_scratch_text(r.error).c_str());
    for (const auto& ch : r.checks) {
        // A golden written or rewritten is always shown: it changed a committed file.
        bool wrote = ch.golden_write != check::CheckResult::GoldenWrite::none;
        if (!ch.passed || verbose || wrote)
            std::printf("    %s %s: %s\n", ch.passed ? (wrote ? "WROTE" : "ok  ") : "FAIL", ch.what.c_str(), ch.detail.c_str());
    }
    for (const auto& v : r.validation) std::printf("    validation: %s\n", v.c_str());
    std::fflush(stdout);
}

// The flags a -j worker repeats from this run.
std::vector<std::string> worker_args(const TestOptions& o, const CommonOptions& c) {
    std::vector<std::string> a;
    if (o.ci) a.push_back("--ci");
    if (o.update) a.push_back("--update");
    if (o.no_validation) a.push_back("--no-validation");
    if (o.verbose) a.push_back("-v");
    a.insert(a.end(), {"--fail-dir", fs::absolute(o.fail_dir).string()});
    if (!o.report_dir.empty()) a.insert(a.end(), {"--report", fs::absolute(o.report_dir).string()});
    if (!c.device.empty()) a.insert(a.end(), {"--device", c.device});
    if (c.no_cache) a.push_back("--no-cache");
    a.insert(a.end(), {"--timeout", std::to_string(c.timeout_s)});
    if (!c.exercise.empty()) a.insert(a.end(), {"--exercise", fs::absolute(c.exercise).string()});
    return a;
}

// Runs the units in this process. A case whose shader runs away fails; its device is abandoned
// and the remaining cases run on a fresh one from the slot (the caller ends the process without
// waiting for the old one: slot.any_hung()).
void run_here(const std::vector<TestUnit>& units, const TestOptions& o, vk::ContextSlot& slot,
              const check::RunOptions& base, RunSummary& out) {
    for (const auto& u : units) {
        check::RunOptions ro = base;
        ro.cases = u.cases;
        ro.output_stem = u.stem;
        if (u.selected() == 0) continue;
        for (auto& r : check::run_preset_tests(slot, u.toml, ro)) {
            out.entries.push_back({u.where, std::move(r)});
            print_case(out.entries.back(), o.verbose);
        }
    }
}

void print_summary(const RunSummary& s) {
    Counts n = count(s.entries);
    if (n.goldens_written || n.goldens_rewritten)
        std::printf("goldens: %d written, %d rewritten (look at them before committing)\n", n.goldens_written, n.goldens_rewritten);
    if (n.failed) {
        std::printf("The following cases FAILED:\n");
        for (const auto& e : s.entries)
            if (!e.result.passed && !e.result.skipped) std::printf("    %s: %s\n", e.where.c_str(), e.result.name.c_str());
    }
    std::printf("%d passed, %d failed", n.passed, n.failed);
    if (n.skipped) std::printf(", %d skipped", n.skipped);
    std::printf(" (%s)\n", s.device.c_str());
}

} // namespace

int test(const TestOptions& o, const CommonOptions& c) {
    // A -j worker ends with its parent (Ctrl-C, a CI timeout): no orphan keeps a device busy.
    if (!o.worker_json.empty()) prctl(PR_SET_PDEATHSIG, SIGTERM);
    std::vector<std::string> args = o.targets;
    if (args.empty()) args = {exec::presets_dir().string(), (exec::presets_dir().parent_path() / "tests" / "graphs").string()};
    // Outputs are checked before anything runs: a path printed must be a file written.
    if (o.report_failures_only && o.report_dir.empty()) {
        Error e = make_error("--report-failures-only needs --report DIR: it says what the report lists");
        e.code = ExitCode::usage;
        return report(e);
    }
    if (!o.report_dir.empty())
        if (auto s = check_output_dir(o.report_dir, "--report"); !s) return report(s.error());
    // The default fail-dir is used only when a golden fails, so a read-only cwd with passing
    // goldens stays fine; an explicit --fail-dir must be writable up front.
    if (o.fail_dir != TestOptions{}.fail_dir || fs::exists(o.fail_dir))
        if (auto s = check_output_dir(o.fail_dir, "--fail-dir"); !s) return report(s.error());
    for (const auto& [file, flag] : {std::pair{o.junit, "--junit"}, std::pair{o.json, "--json"}, std::pair{o.worker_json, "--worker-json"}})
        if (!file.empty())
            if (auto s = check_output_file(file, flag); !s) return report(s.error());

    // A -j worker runs the share its parent planned: selection and shards are already applied.
    auto units = o.worker_plan.empty() ? collect_units(args) : read_plan(o.worker_plan);
    if (!units) return report(units.error());
    const size_t collected = selected_count(*units);
    if (o.worker_plan.empty())
        if (auto s = select_cases(*units, o.cases); !s) return report(s.error());
    const size_t chosen = selected_count(*units);
    if (chosen == 0) {
        // As test runners do for "no tests collected": nothing tested is not a pass.
        if (collected == 0) std::printf("test: no [[test]] cases in %zu preset(s): nothing tested\n", units->size());
        else std::printf("test: --case selects none of the %zu case(s)\n", collected);
        return static_cast<int>(ExitCode::user);
    }
    Shard shard;
    if (o.worker_plan.empty()) {
        auto sh = shard_from(o.shard);
        if (!sh) return report(sh.error());
        shard = *sh;
    }
    select_shard(*units, shard);
    if (shard.total > 1) {
        std::printf("shard %d/%d: %zu of %zu case(s)\n", shard.index + 1, shard.total, selected_count(*units), chosen);
        if (selected_count(*units) == 0) return 0;  // more shards than cases: this one has none
    }

    check::RunOptions ro;
    const char* ci_env = std::getenv("CI");
    ro.ci = o.ci || (ci_env && std::string(ci_env) == "true");
    ro.update = o.update;
    ro.cache_dir = cache_dir(c);
    ro.fail_dir = o.fail_dir;
    ro.report_dir = o.report_dir;
    ro.timeout = timeout(c);
    auto overlay = exercise_overlay(c);
    if (!overlay) return report(overlay.error());
    ro.overlay_dirs = *overlay;
    // An exercise copy is the student's: its renders must never become goldens.
    if (!ro.overlay_dirs.empty()) ro.ci = true, ro.update = false;

    std::vector<TestUnit> active;
    for (const auto& u : *units)
        if (u.selected()) active.push_back(u);
    const int jobs = std::min<int>(o.jobs > 0 ? o.jobs : default_jobs(), static_cast<int>(active.size()));

    auto t0 = std::chrono::steady_clock::now();
    RunSummary summary;
    // Outlives the run: a device that hung must not be destroyed before the process ends.
    std::unique_ptr<vk::ContextSlot> slot;
    if (jobs > 1) {
        auto merged = run_in_workers(active, jobs, worker_args(o, c));
        if (!merged) return report(merged.error());
        summary = std::move(merged.value());
    } else {
        vk::ContextOptions co;
        // Tests always run under the validation layer when it is installed (--no-validation to skip).
        co.validation = !o.no_validation;
        co.device = c.device;
        slot = std::make_unique<vk::ContextSlot>(co);
        auto ctx = slot->get();
        if (!ctx) return report(ctx.error());
        if (!(*ctx)->validation_enabled() && !o.no_validation)
            std::fprintf(stderr, "test: the Khronos validation layer is not installed; running without it\n");
        summary.device = (*ctx)->device_description();
        run_here(active, o, *slot, ro, summary);
    }
    summary.ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();

    if (!o.worker_json.empty()) {
        // A -j worker: the parent prints the summary and writes the outputs.
        if (auto s = write_json_file(o.worker_json, to_json(summary)); !s) return report(s.error());
        if (slot && slot->any_hung()) exit_after_hang(count(summary.entries).failed ? 1 : 0);
        return count(summary.entries).failed ? 1 : 0;
    }
    int rc = count(summary.entries).failed ? 1 : 0;
    if (!o.report_dir.empty()) {
        if (auto s = write_report(o.report_dir, summary.entries, summary.device, summary.ms, o.report_failures_only); !s)
            return report(s.error());
        std::printf("report: %s\n", (fs::path(o.report_dir) / "index.html").string().c_str());
    }
    if (!o.json.empty()) {
        if (auto s = write_json_file(o.json, to_json(summary)); !s) return report(s.error());
        std::printf("json: %s\n", o.json.c_str());
    }
    if (!o.junit.empty()) {
        if (auto s = write_junit(o.junit, summary); !s) return report(s.error());
        std::printf("junit: %s\n", o.junit.c_str());
    }
    print_summary(summary);
    if (slot && slot->any_hung()) {
        std::printf("a runaway shader may still be running on an abandoned device: ending without waiting for it\n");
        exit_after_hang(rc);
    }
    return rc;
}

} // namespace pl::lab
