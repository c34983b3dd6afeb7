// `passlab test -j N`: the presets are shared among N child processes of this executable
// (`passlab test --worker-plan PLAN --worker-json FILE`), each with its own Vulkan instance and
// device, so the validation layer's state and a runaway shader stay in one process. Their
// output is streamed line by line; the parent merges their JSON results for the summary,
// --json, --junit and --report.
#pragma once

#include "results.hpp"
#include "test_select.hpp"

#include <string>
#include <vector>

namespace pl::lab {

// `args` are the flags every worker gets (options of the parent run); the plan (its presets and
// their selected cases) and `--worker-json` are added per worker.
Result<RunSummary> run_in_workers(const std::vector<TestUnit>& units, int jobs, const std::vector<std::string>& args);

// The default of -j: the machine's cores (each lavapipe device also runs LP_NUM_THREADS
// rasterizer threads, so more processes than cores only contend).
int default_jobs();

} // namespace pl::lab
