// Running passlab itself as a child process, output captured, with a hard time limit.
//
// `passlab mutate` runs every mutant in a fresh process: a mutant may run away on the GPU, and a
// runaway cannot be cancelled on every driver (lavapipe), so the device it ran on is abandoned
// with its process instead of being waited on (docs/architecture.md, "runaway shaders").
#pragma once

#include <string>
#include <vector>

namespace pl::lab {

struct ChildResult {
    int exit_code = -1;      // -1 when killed or not started
    bool timed_out = false;  // killed after the time limit
    std::string output;      // stdout and stderr, interleaved
    std::string error;       // why it could not be started
};

// Runs this executable (/proc/self/exe) with `args`; kills its process group after `timeout_s`.
ChildResult run_self(const std::vector<std::string>& args, double timeout_s);

} // namespace pl::lab
