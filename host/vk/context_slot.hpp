// The device a sequence of independent jobs (test cases, gallery thumbnails) runs on. After a
// watchdog timeout the driver may still be running the runaway shader on the old device (on
// lavapipe it keeps its threads until the loop ends), so that Context is abandoned, never
// destroyed or waited for, and the next job gets a fresh one. The caller ends the process with
// std::_Exit once any device hung (unloading the driver under a running shader can hang).
#pragma once

#include "vk/context.hpp"

#include <memory>
#include <vector>

namespace pl::vk {

class ContextSlot {
  public:
    explicit ContextSlot(ContextOptions options) : options_(std::move(options)) {}
    ContextSlot(const ContextSlot&) = delete;
    ContextSlot& operator=(const ContextSlot&) = delete;
    ~ContextSlot();

    // The current device; a fresh one if the last one hung (the first call creates it).
    Result<Context*> get();
    // True once any device of this slot hung: its driver may still run a shader.
    bool any_hung() const { return hung_count_ > 0 || (current_ && current_->hung()); }

  private:
    ContextOptions options_;
    std::unique_ptr<Context> current_;
    int hung_count_ = 0;
};

} // namespace pl::vk
