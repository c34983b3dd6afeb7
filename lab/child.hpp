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
    int signal = 0;          // the signal that ended it (a crash), 0 when it exited or timed out
    std::string output;      // stdout and stderr, interleaved
    std::string error;       // why it could not be started
};

// Runs `program` (a path, or a name looked up on PATH) with `args`, no shell; kills its process
// group after `timeout_s`. Exit code 127: it could not be executed.
ChildResult run_program(const std::string& program, const std::vector<std::string>& args, double timeout_s);
// Runs this executable (/proc/self/exe) with `args`.
ChildResult run_self(const std::vector<std::string>& args, double timeout_s);
// The full path of `name` on PATH, or "" when there is none.
std::string find_on_path(const std::string& name);

} // namespace pl::lab
