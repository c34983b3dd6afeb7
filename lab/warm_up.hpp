// The live lab's warm-up process, for drivers that compile a pipeline's shaders at its first draw
// rather than when it is created. llvmpipe does (20-30 ms per pipeline, one after another on the
// queue's thread), so an edit of an include that ten passes share stalls the first new frame by
// ~250 ms. Every build that compiled the lab also hands to a companion process
// (`passlab warm-up-server`, started with the lab, with its own device), which builds the graph
// too (from the SPIR-V cache the lab's build just filled) and renders one frame of the later half of the passes whose code changed, while the lab's
// own first frame compiles the earlier half: two cores compile at once, and when the lab's frame
// reaches the later passes the driver's on-disk shader cache already holds them. A second device
// in the lab's own process would not do: llvmpipe compiled no faster with two devices in one
// process (measured: docs/cli.md, `--warm-up`).
// It never holds the lab up: the lab does not wait for it, a rebuild that arrives while it still
// works gets no warm-up, and it is killed when the lab ends (a runaway shader in it harms
// nothing). Nothing depends on it: without a shader cache the lab compiles everything itself.
#pragma once

#include "exec/build.hpp"

#include <map>
#include <memory>
#include <optional>
#include <set>
#include <string>
#include <sys/types.h>
#include <vector>

namespace pl::lab {

class WarmUpServer {
  public:
    // Starts `passlab warm-up-server` (this executable); null (and why in `error`) if it cannot.
    // `device` as the lab's --device (the same GPU).
    static std::unique_ptr<WarmUpServer> start(const std::string& device, std::string& error);
    WarmUpServer(const WarmUpServer&) = delete;
    WarmUpServer& operator=(const WarmUpServer&) = delete;
    ~WarmUpServer();  // closes its input, gives it a moment, then kills it

    // Sends a build to warm up (the lab's own toml and options); false when the previous one has
    // not been answered yet (nothing is sent) or the server is gone.
    bool send(const std::filesystem::path& toml, const exec::BuildOptions& bo);
    // An answer line (JSON: ms, passes, error), if one arrived; never blocks.
    std::optional<std::string> poll();
    bool alive() const { return pid_ > 0; }

  private:
    WarmUpServer() = default;
    pid_t pid_ = -1;
    int to_ = -1, from_ = -1;  // its stdin, its stdout
    bool waiting_ = false;     // a job sent and not answered
    std::string partial_;      // an answer line read in part
};

// The child's side: reads one JSON job per line on stdin, answers one line per job on stdout.
int warm_up_server(const std::string& device);

// The passes a warm-up renders: of those whose code differs from `previous` (pass name -> hash of
// kind and SPIR-V; updated), the later half in execution order, which the lab's frame reaches last.
std::set<std::string> warm_up_passes(const exec::CompiledGraph& g, std::map<std::string, size_t>& previous);

} // namespace pl::lab
