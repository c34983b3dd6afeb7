// Test cases as data: a [[test]] of preset.toml is rendered headlessly with a fixed clock and its
// checks (golden, probes, properties) are evaluated on the read-back images. Used by
// `passlab test`; every check is generic, nothing is per preset.
#pragma once

#include "exec/build.hpp"
#include "exec/executor.hpp"
#include "graph/desc.hpp"
#include "vk/context_slot.hpp"

#include <chrono>
#include <filesystem>
#include <optional>
#include <set>
#include <string>
#include <vector>

namespace pl::check {

struct CheckResult {
    std::string what;   // "probe uv=(0.5,0.5)", "golden snapshots/x.png", ...
    bool passed = false;
    std::string detail; // measured values vs tolerance
    std::string expected_file, actual_file, diff_file;  // goldens, for reports
    // A golden written by this run (missing and written locally, or --update): always reported.
    enum class GoldenWrite { none, written, rewritten } golden_write = GoldenWrite::none;
};

struct CaseResult {
    std::string preset, name;
    bool passed = false;
    bool skipped = false;
    std::string skip_reason;
    std::vector<CheckResult> checks;
    std::vector<std::string> validation;  // validation-layer messages seen during the case
    std::string error;                    // build/render error (formatted), if any
    double ms = 0.0;
    std::string image_file;  // the checked image, written when a report is requested
    std::string hint;        // the case's `hint` (course exercises)
    double weight = 1.0;     // the case's points and visibility in `passlab grade` (TestDesc)
    std::string visibility = "visible";
};

struct RunOptions {
    bool ci = false;         // missing golden fails instead of being written
    bool update = false;     // rewrite goldens
    std::filesystem::path cache_dir;
    std::filesystem::path fail_dir;  // where actual/expected/diff images of failures go
    std::filesystem::path report_dir;  // when set, every case's image is written there too
    // Folders whose files shadow the preset's own (a student's exercise copy; see BuildOptions).
    std::vector<std::filesystem::path> overlay_dirs;
    // When set, only these cases run (the others are not reported): `--case`, sharding.
    std::optional<std::set<std::string>> cases;
    // Relative path under fail_dir/report_dir for this preset's images, unique per preset
    // (e.g. "presets/aa/msaa"); empty: the folder's basename as a prefix of the file name.
    std::filesystem::path output_stem;
    std::chrono::milliseconds timeout{std::chrono::seconds(20)};  // GPU watchdog per frame (--timeout)
};

// The output file stem (without extension) of a case: "<output_stem>/<case>" or "<basename>.<case>".
std::filesystem::path case_stem(const RunOptions& opt, const std::filesystem::path& preset_toml, const std::string& name);

// Runs every [[test]] of one preset on the slot's device. A case whose frame exceeds the
// watchdog fails with the runaway passes named; the device it hung is abandoned and the
// remaining cases run on a fresh one.
std::vector<CaseResult> run_preset_tests(vk::ContextSlot& slot, const std::filesystem::path& preset_toml,
                                         const RunOptions& opt);

} // namespace pl::check
