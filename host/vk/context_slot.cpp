#include "vk/context_slot.hpp"

namespace pl::vk {

ContextSlot::~ContextSlot() {
    // A hung device is never destroyed (see the header); a healthy one is.
    if (current_ && current_->hung()) (void)current_.release();
}

Result<Context*> ContextSlot::get() {
    if (current_ && current_->hung()) {
        ++hung_count_;
        (void)current_.release();  // abandoned: the runaway shader may still use everything in it
        options_.verbose = false;  // the device was already named once
    }
    if (!current_) {
        auto ctx = Context::create(options_);
        if (!ctx) return ctx.error();
        current_ = std::move(ctx.value());
    }
    return current_.get();
}

} // namespace pl::vk
