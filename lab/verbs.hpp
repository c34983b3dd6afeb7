// The `passlab` verbs. Each returns the process exit code (see docs/cli.md); main.cpp only
// parses the command line and dispatches.
#pragma once

#include "exec/build.hpp"
#include "util/error.hpp"

#include <array>
#include <chrono>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace pl::lab {

struct CommonOptions {
    std::string device;        // --device
    bool validation = false;   // --validation (also PASSLAB_VALIDATION=1)
    bool no_cache = false;     // --no-cache
    double timeout_s = 20.0;   // --timeout: GPU watchdog per frame
    std::string exercise;      // --exercise DIR: its files shadow the preset's (course exercises)
};

struct RenderOptions {
    std::string preset;
    std::string out_dir;
    std::string size;  // "WxH"
    double time = 0.0;
    int frames = 1;
    double step = 1.0 / 60.0;
    std::vector<std::string> set;
    std::vector<std::string> passes;  // extra images to write
    std::string format;               // "", "png", "exr"
    bool sequence = false;            // --sequence: the output image of every frame, numbered
    std::string video;                // --video FILE.mp4|.gif: every frame encoded by ffmpeg
};

struct TestOptions {
    std::vector<std::string> targets;  // presets or folders; default presets/ and tests/graphs/
    bool ci = false;                   // --ci (also CI=true): missing goldens fail
    bool update = false;               // --update: rewrite goldens (of the selected cases)
    std::vector<std::string> cases;    // --case NAME|GLOB (repeatable): only these cases run
    bool no_validation = false;
    bool verbose = false;
    std::string fail_dir = "test-failures";
    std::string report_dir;  // --report DIR: static HTML with every case
    bool report_failures_only = false;  // --report-failures-only: list (and keep images of) failed cases only
    std::string junit;       // --junit FILE: JUnit XML
    std::string json;        // --json FILE: every case and check as JSON
    int jobs = 0;            // -j N: presets in N processes at once; 0 = default_jobs()
    std::string shard;       // --shard K/N (else TEST_TOTAL_SHARDS / TEST_SHARD_INDEX)
    std::string worker_json; // internal: a -j worker writes its results here for the parent
    std::string worker_plan; // internal: the presets and cases a -j worker runs
};

struct RunOptions {
    std::string preset;
    std::string size;
    double time = 0.0;
    std::vector<std::string> set;
    std::string present = "fifo";  // fifo | mailbox | immediate
    std::string events;  // --events FILE: JSON lines
    double seconds = 0;            // stop after this long (tests); 0 = until closed
    int frames = 0;                // stop after this many frames; 0 = until closed
    bool ui = true;                // the Dear ImGui panel (Tab toggles it at run time)
    bool sidecar = true;           // apply the saved param values (preset.params.toml)
    std::string inspect;           // open the image viewer on this image
    std::string capture;           // save the last frame's window (panel included) to this PNG
    std::string warm_up = "auto";  // auto | on | off (lab/warm_up.hpp)
};

struct BenchOptions {
    std::string preset;
    std::string size;  // "WxH"
    int frames = 60;
    int warmup = 5;
    std::vector<std::string> set;
    std::string json;  // --json FILE
};

struct NewOptions {
    std::string dest;        // the new preset folder (must not exist)
    std::string from;        // PRESET to copy
    bool with_passes = false;  // also copy the passes/ files it reads (they shadow the library)
    std::string exercise;    // --exercise PRESET: copy only that preset's exercise/ (a student's working copy)
};

struct MutateOptions {
    std::vector<std::string> targets;  // presets or trees of presets
    uint64_t seed = 1;                 // which mutants are chosen (deterministic)
    int max = 12;                      // mutants per preset (0 = all)
    bool library = false;              // also mutate the passes/ files the preset reads
    double child_timeout_s = 180.0;    // a mutant's whole test run; then it counts as a runaway
    bool verbose = false;              // show the changed line of every mutant, not only survivors
    std::string json;                  // --json FILE: every mutant and its outcome
};

struct ImportVerbOptions {
    std::string source;     // Shadertoy JSON / mainImage file / folder, or ISF .fs
    std::string dest;       // -o: the new preset folder (must not exist)
    std::string kind;       // --kind shadertoy|isf
    bool golden = true;     // --no-golden: no [[test]] golden case (corpora that bring their own)
};

struct GradeOptions {
    std::string preset;
    std::string out_dir = "grade-out";  // actual/expected/diff images of failed cases
    std::string json_file;              // --json: the grade for a course platform
    std::string format = "passlab";     // --format: passlab | gradescope (the --json schema)
};

int render(const RenderOptions& o, const CommonOptions& c);
int grade(const GradeOptions& o, const CommonOptions& c);
int import_source(const ImportVerbOptions& o);
int new_preset(const NewOptions& o, const CommonOptions& c);
int bench(const BenchOptions& o, const CommonOptions& c);
int run(const RunOptions& o, const CommonOptions& c);
int test(const TestOptions& o, const CommonOptions& c);
int check(const std::string& preset, const std::vector<std::string>& set, const CommonOptions& c,
          const std::string& spirv_dir = {}, const std::string& json_file = {});
int list(bool verbose, bool catalogue, bool course);
int gallery(const std::string& out_dir, int width, const CommonOptions& c);
int graph_dot(const std::string& preset, const CommonOptions& c);
int mutate(const MutateOptions& o, const CommonOptions& c);

// Shared helpers.
int report(const Error& e);  // prints the error, returns its exit code
// After a GPU watchdog timeout the driver may still be running the shader; waiting for it or
// unloading the driver could hang, so the process ends here after reporting.
[[noreturn]] void exit_after_hang(int code);
std::string cache_dir(const CommonOptions& c);
std::chrono::milliseconds timeout(const CommonOptions& c);  // --timeout as the watchdog's duration
Result<std::optional<std::array<int, 2>>> parse_size(const std::string& s);

// What every verb that renders starts with: resolve PRESET, apply --size and --set, build.
struct LoadedPreset {
    std::filesystem::path toml;
    exec::BuildOptions options;  // kept for rebuilds (live reload)
};
Result<LoadedPreset> resolve_and_configure(const std::string& preset, const std::string& size,
                                           const std::vector<std::string>& set, const CommonOptions& c);
// Every preset.toml under ARG: a preset folder, a .toml, a name, or a tree of presets (sorted).
Result<std::vector<std::filesystem::path>> collect_presets(const std::string& arg);
// --exercise DIR: the folder must exist; returns it as an overlay list (empty without the flag).
Result<std::vector<std::filesystem::path>> exercise_overlay(const CommonOptions& c);
// Prints which files of the exercise folder shadow the preset's, and warns about those that
// shadow nothing the preset reads (a misspelt name would otherwise be silently ignored).
// Returns how many files of the folder the build used.
int describe_exercise(const CommonOptions& c, const exec::CompiledGraph& g);
// The files an exercise of this preset is expected to hold (relative names): those of the
// preset's own exercise/ folder, else the files of the preset's folder the build read.
std::vector<std::string> exercise_files(const std::filesystem::path& preset_toml, const exec::CompiledGraph& g);

// Output paths are checked before any work: an unwritable --report/--fail-dir/--out/-o (or one
// that names a file) is an environment error (exit 3), never a path printed but not written.
Status check_output_dir(const std::string& dir, const std::string& flag);
Status check_output_file(const std::string& file, const std::string& flag);

} // namespace pl::lab
