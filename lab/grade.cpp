// `passlab grade PRESET --exercise DIR`: a student's copy of some of a preset's shaders (the
// files in DIR shadow the preset's own, by name) is run through the preset's [[test]] cases.
// Goldens are the reference's images, so each case answers "does your version do what the
// reference does?"; a failed case prints every measured figure, its `hint` and the paths of
// the actual / expected / diff images. Goldens are never written here (a student's image must
// not become the reference), so a missing golden fails.
#include "verbs.hpp"

#include "check/checks.hpp"
#include "vk/context_slot.hpp"

#include <cstdio>
#include <filesystem>

namespace fs = std::filesystem;

namespace pl::lab {

int grade(const GradeOptions& o, const CommonOptions& c) {
    if (c.exercise.empty()) {
        Error e = make_error("passlab grade needs --exercise DIR (the folder with your copies of the preset's files)");
        e.code = ExitCode::usage;
        return report(e);
    }
    if (auto s = check_output_dir(o.out_dir, "--out"); !s) return report(s.error());
    auto lp = resolve_and_configure(o.preset, "", {}, c);
    if (!lp) return report(lp.error());
    // Build once first: a compile error in the student's file is the first thing to fix, and
    // it is reported with file:line:col in their copy.
    auto built = exec::build_graph(lp->toml, lp->options);
    if (!built) {
        std::fputs(built.error().format().c_str(), stderr);
        std::printf("grade: your files do not build yet (see above); 0 cases graded\n");
        return static_cast<int>(ExitCode::user);
    }
    // A folder that shadows nothing would grade the reference itself and pass every case.
    if (describe_exercise(c, *built) == 0) {
        std::string expected;
        for (const auto& f : exercise_files(lp->toml, *built)) expected += (expected.empty() ? "" : ", ") + f;
        std::printf("grade: nothing graded: %s holds none of the files this exercise asks for (%s); "
                    "copy them from the preset's exercise/ folder and keep their names\n",
                    c.exercise.c_str(), expected.empty() ? "the preset's shaders" : expected.c_str());
        return static_cast<int>(ExitCode::user);
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

    check::RunOptions ro;
    ro.ci = true;      // never write a golden from a student's render
    ro.update = false;
    ro.cache_dir = cache_dir(c);
    ro.fail_dir = o.out_dir;
    ro.overlay_dirs = lp->options.overlay_dirs;
    ro.timeout = timeout(c);
    auto results = check::run_preset_tests(slot, lp->toml, ro);

    int passed = 0, failed = 0, skipped = 0;
    for (const auto& r : results) {
        if (r.skipped) {
            ++skipped;
            std::printf("SKIP %s (%s)\n", r.name.c_str(), r.skip_reason.c_str());
            continue;
        }
        (r.passed ? passed : failed)++;
        std::printf("%s %s\n", r.passed ? "PASS" : "FAIL", r.name.c_str());
        if (!r.error.empty()) std::printf("%s", r.error.c_str());
        for (const auto& ch : r.checks) {
            std::printf("    %s %s: %s\n", ch.passed ? "ok  " : "FAIL", ch.what.c_str(), ch.detail.c_str());
            if (!ch.passed && !ch.diff_file.empty())
                std::printf("         images: %s (yours), %s (reference), %s (difference)\n", ch.actual_file.c_str(),
                            ch.expected_file.c_str(), ch.diff_file.c_str());
        }
        for (const auto& v : r.validation) std::printf("    validation: %s\n", v.c_str());
        if (!r.passed && !r.hint.empty()) std::printf("    hint: %s\n", r.hint.c_str());
    }
    std::printf("grade: %d of %d cases pass with %s\n", passed, passed + failed, c.exercise.c_str());
    std::printf("%d passed, %d failed", passed, failed);
    if (skipped) std::printf(", %d skipped", skipped);
    std::printf(" (%s)\n", (*ctx)->device_description().c_str());
    if (slot.any_hung()) exit_after_hang(failed ? 1 : 0);
    return failed ? 1 : 0;
}

} // namespace pl::lab
