// passlab: command-line entry. Parses arguments with CLI11 and calls one verb; all work lives in
// the verbs and the host library.
#include "verbs.hpp"
#include "warm_up.hpp"
#include "vk/check.hpp"

#include <CLI/CLI.hpp>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <new>

namespace {

// CLI11's number checks pass NaN (every comparison with it is false) and inf; these refuse both.
// A value within (lo, hi] (`open_low`) or [lo, hi].
CLI::Validator finite_in(double lo, double hi, bool open_low = false) {
    return CLI::Validator(
        [=](std::string& s) -> std::string {
            char* end = nullptr;
            double v = std::strtod(s.c_str(), &end);
            if (end == s.c_str() || *end || !std::isfinite(v)) return "'" + s + "' is not a finite number";
            if (open_low ? v <= lo : v < lo) return "'" + s + "' must be " + (open_low ? "> " : ">= ") + std::to_string(lo);
            if (v > hi) return "'" + s + "' must be <= " + std::to_string(hi);
            return {};
        },
        "FINITE");
}

constexpr double max_seconds = 1e7;  // ~4 months of scene time; far beyond any use, far below overflow

} // namespace

int main(int argc, char** argv) {
    using namespace pl::lab;
    CLI::App app{"passlab: a shader lab for real-time rendering (Vulkan)"};
    app.require_subcommand(1);
    app.set_version_flag("--version", "passlab 0.1.0");

    CommonOptions common;
    if (const char* v = std::getenv("PASSLAB_VALIDATION")) common.validation = std::string(v) == "1";
    auto add_common = [&](CLI::App* sub) {
        sub->add_option("--device", common.device, "Vulkan device: index or name substring (default: PASSLAB_DEVICE, else the best GPU, else lavapipe)");
        sub->add_flag("--validation", common.validation, "Enable the Khronos validation layer");
        sub->add_flag("--no-cache", common.no_cache, "Do not read or write the SPIR-V cache");
        sub->add_option("--timeout", common.timeout_s, "Seconds a frame may take before it is cut off")->check(finite_in(0, 86400, true));
    };
    // Course exercises: the files in DIR shadow the preset's own of the same name.
    auto add_exercise = [&](CLI::App* sub) {
        sub->add_option("--exercise", common.exercise, "Folder whose files shadow the preset's (a student's exercise copy)");
    };

    RenderOptions ro;
    auto* render_cmd = app.add_subcommand("render", "Render a preset headlessly to image files");
    render_cmd->add_option("preset", ro.preset, "Preset folder, preset.toml, or name")->required();
    render_cmd->add_option("-o,--out", ro.out_dir, "Output folder")->required();
    render_cmd->add_option("--size", ro.size, "Size WxH (default: [view].size)");
    render_cmd->add_option("--time", ro.time, "Time of the last frame, seconds")->check(finite_in(-max_seconds, max_seconds));
    render_cmd->add_option("--frames", ro.frames, "Number of frames to render")->check(CLI::Range(1, 100000));
    render_cmd->add_option("--step", ro.step, "Seconds between frames")->check(finite_in(0, 3600, true));
    render_cmd->add_option("--set", ro.set, "Param override name=value (repeatable)");
    render_cmd->add_option("--pass", ro.passes, "Also write this image (repeatable)");
    render_cmd->add_option("--format", ro.format, "Force png or exr")->check(CLI::IsMember({"png", "exr"}));
    render_cmd->add_flag("--sequence", ro.sequence, "Write the output image of every frame: <preset>.00000.png, ...");
    render_cmd->add_option("--video", ro.video, "Encode every frame into FILE.mp4 or FILE.gif with ffmpeg (1/step frames per second)");
    add_common(render_cmd);
    add_exercise(render_cmd);

    TestOptions to;
    auto* test_cmd = app.add_subcommand("test", "Run presets' [[test]] cases headlessly (goldens, probes, properties)");
    test_cmd->add_option("presets", to.targets, "Presets or folders (default: presets/ and tests/graphs/)");
    test_cmd->add_flag("--ci", to.ci, "Missing goldens fail (also when CI=true)");
    test_cmd->add_flag("--update", to.update, "Rewrite goldens");
    test_cmd->add_option("--case", to.cases, "Only this case (a name or a glob such as 'edge-*'; repeatable)");
    test_cmd->add_option("--junit", to.junit, "Write JUnit XML (one testcase per case, images as attachments) to FILE");
    test_cmd->add_option("--json", to.json, "Write every case and check as JSON to FILE");
    test_cmd->add_option("-j,--jobs", to.jobs, "Presets run in N processes at once (default: the number of cores)")->check(CLI::Range(1, 256));
    test_cmd->add_option("--shard", to.shard, "Run shard K of N (1-based; also TEST_TOTAL_SHARDS / TEST_SHARD_INDEX)");
    test_cmd->add_option("--worker-json", to.worker_json, "Internal: results of a -j worker")->group("");
    test_cmd->add_option("--worker-plan", to.worker_plan, "Internal: what a -j worker runs")->group("");
    test_cmd->add_flag("--no-validation", to.no_validation, "Do not enable the validation layer");
    test_cmd->add_flag("-v,--verbose", to.verbose, "Print every check, not only failures");
    test_cmd->add_option("--fail-dir", to.fail_dir, "Where actual/expected/diff images of failures go");
    test_cmd->add_option("--report", to.report_dir, "Write an HTML report with every case into this folder");
    test_cmd->add_flag("--report-failures-only", to.report_failures_only,
                       "The report lists failed and skipped cases only (passes are counted) and keeps no images of passes");
    add_common(test_cmd);
    add_exercise(test_cmd);

    std::string preset;
    std::vector<std::string> set;
    auto* check_cmd = app.add_subcommand("check", "Parse, compile, reflect and validate a preset; no rendering");
    check_cmd->add_option("preset", preset, "Preset folder, preset.toml, or name")->required();
    check_cmd->add_option("--set", set, "Param override name=value (repeatable)");
    std::string spirv_dir;
    check_cmd->add_option("--spirv", spirv_dir, "Also write every pass's SPIR-V into this folder");
    std::string check_json;
    check_cmd->add_option("--json", check_json, "Also write passes, images, buffers, params (with their widgets) and tests as JSON to FILE ('-': stdout, alone)");
    add_common(check_cmd);
    add_exercise(check_cmd);

    bool verbose = false;
    auto* list_cmd = app.add_subcommand("list", "List the presets with family and summary");
    list_cmd->add_flag("-v,--verbose", verbose, "Also print each preset's folder, level, course citations and exercise");
    bool catalogue = false;
    list_cmd->add_flag("--catalogue", catalogue, "Print the technique catalogue (docs/catalogue.md) as Markdown");
    bool course = false;
    list_cmd->add_flag("--course", course, "Print the course path (docs/course.md): units in teaching order, exercises and effort");

    RunOptions rn;
    auto* run_cmd = app.add_subcommand("run", "Live lab: a window with hot reload of every file the preset reads");
    run_cmd->add_option("preset", rn.preset, "Preset folder, preset.toml, or name")->required();
    run_cmd->add_option("--size", rn.size, "Window / view size WxH");
    run_cmd->add_option("--time", rn.time, "Start time, seconds")->check(finite_in(-max_seconds, max_seconds));
    run_cmd->add_option("--set", rn.set, "Param override name=value (repeatable)");
    run_cmd->add_option("--present", rn.present, "fifo, mailbox or immediate")->check(CLI::IsMember({"fifo", "mailbox", "immediate"}));
    run_cmd->add_option("--events", rn.events, "Write JSON-lines events (reloads, frames) to this file");
    run_cmd->add_option("--seconds", rn.seconds, "Quit after this many seconds")->check(finite_in(0, max_seconds));
    run_cmd->add_option("--frames", rn.frames, "Quit after this many frames")->check(CLI::NonNegativeNumber);
    run_cmd->add_flag("!--no-ui", rn.ui, "Start without the panel (Tab shows it)");
    run_cmd->add_flag("!--no-sidecar", rn.sidecar, "Ignore saved param values (preset.params.toml)");
    run_cmd->add_option("--inspect", rn.inspect, "Open the image viewer on this image");
    run_cmd->add_option("--capture", rn.capture, "With --frames: save the last frame's window, panel included, to this PNG");
    run_cmd->add_option("--warm-up", rn.warm_up, "auto (on for CPU devices), on or off: a companion process compiles half of a reload's changed passes in parallel")
        ->check(CLI::IsMember({"auto", "on", "off"}));
    add_common(run_cmd);
    add_exercise(run_cmd);
    // The live lab's companion process (lab/warm_up.hpp): not for users.
    std::string warm_device;
    auto* warm_cmd = app.add_subcommand("warm-up-server", "Internal: the live lab's warm-up process")->group("");
    warm_cmd->add_option("--device", warm_device, "Vulkan device");

    BenchOptions bo;
    auto* bench_cmd = app.add_subcommand("bench", "Frame and per-pass GPU timings of a preset, peak memory");
    bench_cmd->add_option("preset", bo.preset, "Preset folder, preset.toml, or name")->required();
    bench_cmd->add_option("--size", bo.size, "Size WxH (default: [view].size)");
    bench_cmd->add_option("--frames", bo.frames, "Measured frames")->check(CLI::Range(1, 100000));
    bench_cmd->add_option("--warmup", bo.warmup, "Frames rendered before measuring")->check(CLI::Range(0, 1000));
    bench_cmd->add_option("--set", bo.set, "Param override name=value (repeatable)");
    bench_cmd->add_option("--json", bo.json, "Also write the figures as JSON to this file");
    add_common(bench_cmd);
    add_exercise(bench_cmd);

    std::string gallery_dir;
    int gallery_width = 320;
    auto* gallery_cmd = app.add_subcommand("gallery", "Render every preset's thumbnail into an HTML gallery and a contact sheet");
    gallery_cmd->add_option("-o,--out", gallery_dir, "Output folder")->required();
    gallery_cmd->add_option("--width", gallery_width, "Thumbnail width in pixels")->check(CLI::Range(16, 2048));
    add_common(gallery_cmd);

    bool dot = false;
    auto* graph_cmd = app.add_subcommand("graph", "Print a preset's pass graph");
    graph_cmd->add_option("preset", preset, "Preset folder, preset.toml, or name")->required();
    graph_cmd->add_flag("--dot", dot, "Graphviz dot output (the only format so far)");
    add_common(graph_cmd);

    GradeOptions go;
    auto* grade_cmd = app.add_subcommand("grade", "Grade a student's exercise copy against the preset's test cases");
    grade_cmd->add_option("preset", go.preset, "Preset folder, preset.toml, or name")->required();
    grade_cmd->add_option("--out", go.out_dir, "Folder for the images of failed cases (default grade-out)");
    grade_cmd->add_option("--json", go.json_file, "Also write the grade as JSON (per case: status, score, figures, hint, images)");
    grade_cmd->add_option("--format", go.format, "Schema of --json: passlab (default) or gradescope (Gradescope's results.json)")
        ->check(CLI::IsMember({"passlab", "gradescope"}));
    add_common(grade_cmd);
    add_exercise(grade_cmd);
    grade_cmd->get_option("--exercise")->required();

    NewOptions no;
    auto* new_cmd = app.add_subcommand("new", "Start a preset from a copy of another (never overwrites)");
    new_cmd->add_option("dest", no.dest, "New preset folder (must not exist)")->required();
    auto* from_opt = new_cmd->add_option("--from", no.from, "Preset to copy: folder, preset.toml, or name");
    auto* new_ex_opt = new_cmd->add_option("--exercise", no.exercise,
                                           "Copy only PRESET's exercise/ files: a student's working copy to grade");
    from_opt->excludes(new_ex_opt);
    new_ex_opt->excludes(from_opt);
    new_cmd->add_flag("--with-passes", no.with_passes, "Also copy the passes/ files it reads, to edit them locally");
    add_common(new_cmd);

    MutateOptions mo;
    auto* mutate_cmd = app.add_subcommand("mutate", "Mutation testing: can the preset's tests catch a broken formula?");
    mutate_cmd->add_option("presets", mo.targets, "Presets (folders, preset.toml, names) or trees of presets")->required();
    mutate_cmd->add_option("--seed", mo.seed, "Which mutants are chosen (the same on every machine)");
    mutate_cmd->add_option("--max", mo.max, "Mutants per preset (0 = all of them)")->check(CLI::NonNegativeNumber);
    mutate_cmd->add_flag("--library", mo.library, "Also mutate the passes/ files the preset reads");
    mutate_cmd->add_option("--child-timeout", mo.child_timeout_s, "Seconds for one mutant's test run before it counts as a runaway")
        ->check(CLI::PositiveNumber);
    mutate_cmd->add_flag("-v,--verbose", mo.verbose, "Show the changed line of every mutant");
    mutate_cmd->add_option("--json", mo.json, "Write every mutant and its outcome to FILE");
    add_common(mutate_cmd);

    ImportVerbOptions io;
    auto* import_cmd = app.add_subcommand("import", "Turn a Shadertoy or ISF shader into a preset folder (never overwrites)");
    import_cmd->add_option("source", io.source, "Shadertoy .json, .glsl/.frag with mainImage, a folder of tabs, or an ISF .fs")->required();
    import_cmd->add_option("-o,--out", io.dest, "New preset folder (must not exist)")->required();
    import_cmd->add_option("--kind", io.kind, "Force the source family")->check(CLI::IsMember({"shadertoy", "isf"}));
    import_cmd->add_flag("!--no-golden", io.golden, "Do not add the [[test]] golden case");

    try {
        app.parse(argc, argv);
    } catch (const CLI::ParseError& e) {
        int rc = app.exit(e);
        return rc == 0 ? 0 : 2;  // usage errors exit 2 (docs/cli.md)
    }

    auto dispatch = [&]() -> int {
    if (render_cmd->parsed()) return render(ro, common);
    if (test_cmd->parsed()) return test(to, common);
    if (check_cmd->parsed()) return check(preset, set, common, spirv_dir, check_json);
    if (list_cmd->parsed()) return list(verbose, catalogue, course);
    if (bench_cmd->parsed()) return bench(bo, common);
    if (run_cmd->parsed()) return run(rn, common);
    if (warm_cmd->parsed()) return warm_up_server(warm_device);
    if (gallery_cmd->parsed()) return gallery(gallery_dir, gallery_width, common);
    if (graph_cmd->parsed()) return graph_dot(preset, common);
    if (new_cmd->parsed()) return new_preset(no, common);
    if (grade_cmd->parsed()) return grade(go, common);
    if (mutate_cmd->parsed()) return mutate(mo, common);
    if (import_cmd->parsed()) return import_source(io);
    return 2;
    };
    try {
        return dispatch();
    } catch (const pl::vk::DeviceLost& e) {
        // Outside the live lab (which recreates the device) a lost device ends the verb.
        std::fprintf(stderr, "passlab: error: the Vulkan device was lost (%s)\n"
                             "    hint: the driver reset the GPU, usually after a shader ran too long; run again\n", e.what());
        return 3;
    } catch (const std::bad_alloc&) {
        // A host allocation too large for the machine (a readback of a huge image under a
        // memory limit): an environment error, exit 3, not an abort.
        std::fputs("passlab: error: out of memory (a host allocation failed)\n"
                   "    hint: make the images or buffers smaller (--size, size expressions)\n", stderr);
        return 3;
    }
}
