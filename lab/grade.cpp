// `passlab grade PRESET --exercise DIR`: a student's copy of some of a preset's shaders (the
// files in DIR shadow the preset's own, by name) is run through the preset's [[test]] cases.
// Goldens are the reference's images, so each case answers "does your version do what the
// reference does?"; a failed case prints every measured figure, its `hint` and the paths of
// the actual / expected / diff images. Goldens are never written here (a student's image must
// not become the reference), so a missing golden fails. Each case is worth its `weight`; cases
// whose `visibility` is not "visible" are graded without showing their figures. `--json FILE`
// writes the same result for a course platform (passlab's schema, or Gradescope's).
#include "grade_results.hpp"
#include "results.hpp"
#include "verbs.hpp"

#include "check/checks.hpp"
#include "graph/parse.hpp"
#include "vk/context_slot.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>

namespace fs = std::filesystem;

namespace pl::lab {

namespace {

// The cases as the reference declares them, all failed: what a platform gets when the student's
// files cannot be graded at all (so a submission that does not compile scores 0, not nothing).
std::vector<check::CaseResult> declared_cases(const fs::path& toml) {
    std::vector<check::CaseResult> out;
    auto desc = graph::parse_graph_file(toml);
    if (!desc) return out;
    for (const auto& t : desc->tests) {
        check::CaseResult r;
        r.preset = toml.parent_path().string();
        r.name = t.name;
        r.weight = t.weight;
        r.visibility = t.visibility;
        out.push_back(r);
    }
    return out;
}

struct Output {
    const GradeOptions& o;
    GradeSummary summary;
    std::chrono::steady_clock::time_point t0 = std::chrono::steady_clock::now();

    // Writes --json FILE if asked; a failed write is an environment error (exit 3).
    int finish(int code) {
        if (o.json_file.empty()) return code;
        summary.seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - t0).count();
        auto j = o.format == "gradescope" ? gradescope_json(summary) : grade_json(summary);
        if (auto s = write_json_file(o.json_file, j); !s) return report(s.error());
        std::printf("grade: wrote %s (%s)\n", o.json_file.c_str(), o.format.c_str());
        return code;
    }
    int not_graded(const fs::path& toml, const std::string& why) {
        summary.not_graded = why;
        summary.cases = declared_cases(toml);
        return finish(static_cast<int>(ExitCode::user));
    }
};

void print_case(const check::CaseResult& r) {
    if (r.skipped) {
        std::printf("SKIP %s (%s)\n", r.name.c_str(), r.skip_reason.c_str());
        return;
    }
    std::printf("%s %s", r.passed ? "PASS" : "FAIL", r.name.c_str());
    if (r.weight != 1.0) std::printf(" (%g points)", r.weight);
    if (!shows_figures(r)) {
        std::printf(" (%s case: figures not shown)\n", r.visibility.c_str());
        return;
    }
    std::printf("\n%s", case_text(r).c_str());
}

} // namespace

int grade(const GradeOptions& o, const CommonOptions& c) {
    if (c.exercise.empty()) {
        Error e = make_error("passlab grade needs --exercise DIR (the folder with your copies of the preset's files)");
        e.code = ExitCode::usage;
        return report(e);
    }
    if (o.format != "passlab" && o.format != "gradescope") {
        Error e = make_error("--format " + o.format + ": expected passlab or gradescope");
        e.code = ExitCode::usage;
        return report(e);
    }
    if (o.format != "passlab" && o.json_file.empty()) {
        Error e = make_error("--format " + o.format + " is the schema of --json FILE; add --json FILE "
                             "(on Gradescope: --json /autograder/results/results.json)");
        e.code = ExitCode::usage;
        return report(e);
    }
    if (auto s = check_output_dir(o.out_dir, "--out"); !s) return report(s.error());
    if (!o.json_file.empty())
        if (auto s = check_output_file(o.json_file, "--json"); !s) return report(s.error());
    auto lp = resolve_and_configure(o.preset, "", {}, c);
    if (!lp) return report(lp.error());
    Output out{o, {}};
    out.summary.preset = o.preset;
    out.summary.exercise = c.exercise;
    // Build once first: a compile error in the student's file is the first thing to fix, and
    // it is reported with file:line:col in their copy.
    auto built = exec::build_graph(lp->toml, lp->options);
    if (!built) {
        std::string msg = built.error().format();
        std::fputs(msg.c_str(), stderr);
        std::printf("grade: your files do not build yet (see above); 0 cases graded\n");
        return out.not_graded(lp->toml, "your files do not build yet:\n" + msg);
    }
    // A folder that shadows nothing would grade the reference itself and pass every case.
    if (describe_exercise(c, *built) == 0) {
        std::string expected;
        for (const auto& f : exercise_files(lp->toml, *built)) expected += (expected.empty() ? "" : ", ") + f;
        char msg[1024];
        std::snprintf(msg, sizeof msg,
                      "nothing graded: %s holds none of the files this exercise asks for (%s); "
                      "copy them from the preset's exercise/ folder and keep their names",
                      c.exercise.c_str(), expected.empty() ? "the preset's shaders" : expected.c_str());
        std::printf("grade: %s\n", msg);
        return out.not_graded(lp->toml, msg);
    }
    if (built->desc.tests.empty()) {
        Error e = make_error("preset " + lp->toml.string() + " has no [[test]] cases to grade against");
        return report(e);
    }

    vk::ContextOptions co;
    co.validation = true;  // as in `passlab test`: a validation message fails the case
    co.device = c.device;
    vk::ContextSlot slot(co);
    auto ctx = slot.get();
    if (!ctx) return report(ctx.error());
    out.summary.device = (*ctx)->device_description();

    check::RunOptions ro;
    ro.ci = true;      // never write a golden from a student's render
    ro.update = false;
    ro.cache_dir = cache_dir(c);
    ro.fail_dir = o.out_dir;
    ro.overlay_dirs = lp->options.overlay_dirs;
    ro.timeout = timeout(c);
    out.summary.cases = check::run_preset_tests(slot, lp->toml, ro);

    for (const auto& r : out.summary.cases) print_case(r);
    Score sc = score_of(out.summary);
    std::printf("grade: %d of %d cases pass with %s", sc.passed, sc.passed + sc.failed, c.exercise.c_str());
    std::printf(" (score %g of %g)\n", sc.score, sc.max_score);
    std::printf("%d passed, %d failed", sc.passed, sc.failed);
    if (sc.skipped) std::printf(", %d skipped", sc.skipped);
    std::printf(" (%s)\n", out.summary.device.c_str());
    int code = out.finish(sc.failed ? 1 : 0);
    if (slot.any_hung()) exit_after_hang(code);
    return code;
}

} // namespace pl::lab
