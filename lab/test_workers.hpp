// `passlab test -j N`: presets run in up to N child processes of this executable at once, each
// `passlab test PRESET --worker-json FILE` with its own Vulkan instance and device (one device
// per process keeps the validation layer's state and a runaway shader to one preset). Each
// child's output is printed whole when it ends (never interleaved), and the parent merges the
// children's JSON results for the summary, --json, --junit and --report.
#pragma once

#include "results.hpp"
#include "test_select.hpp"

#include <string>
#include <vector>

namespace pl::lab {

// `args` are the flags every worker gets (options of the parent run); `--case` per selected
// case and `--worker-json` are added per unit.
Result<RunSummary> run_in_workers(const std::vector<TestUnit>& units, int jobs, const std::vector<std::string>& args);

// The default of -j: the machine's cores (each lavapipe device also runs LP_NUM_THREADS
// rasterizer threads, so more processes than cores only contend).
int default_jobs();

} // namespace pl::lab
