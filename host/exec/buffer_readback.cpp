// Buffers read back by the host: a whole buffer after the last frame (`read_buffer`, for buffer
// checks) and, after every frame, the counter words buffers declare (`counter = { offset,
// capacity }`): one 4-byte copy per counter into a small host-visible buffer, so watching an
// append counter for overflow costs a copy, not a readback of the buffer.
#include "exec/barriers.hpp"
#include "exec/bind.hpp"
#include "exec/executor.hpp"
#include "vk/check.hpp"

#include <cstring>

namespace pl::exec {

std::string overflow_message(const CounterReading& c) {
    return "buffer '" + c.buffer + "' counted " + std::to_string(c.overflow_count) + " > capacity " + std::to_string(c.capacity) +
           " after frame " + std::to_string(c.overflow_frame);
}

Result<std::vector<uint32_t>> Executor::read_buffer(const std::string& name) {
    auto it = res_.buffers.find(name);
    if (it == res_.buffers.end()) return no_resource("buffer", name, res_.buffers);
    PhysBuffer& pb = *it->second.phys[last_parity()];  // history buffers alternate
    VkDeviceSize bytes = pb.buffer.size;
    vk::Buffer staging = vk::create_buffer(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    Status st = ctx_.run_once(
        [&](VkCommandBuffer cb) {
            BarrierBatch batch;
            require(batch, pb, usage_of(Access::transfer_src, 0));
            batch.flush(cb);
            VkBufferCopy c{0, 0, bytes};
            vkCmdCopyBuffer(cb, pb.buffer.buffer, staging.buffer, 1, &c);
            transfer_to_host(cb);
        },
        timeout_);
    if (!st) return st.error();
    std::vector<uint32_t> words(static_cast<size_t>(bytes / 4));
    std::memcpy(words.data(), staging.mapped, words.size() * 4);
    return words;
}

Status Executor::create_counters() {
    const CompiledGraph& g = *graph_;
    auto env = size_env(g.desc, g.view);
    for (const auto& d : g.desc.buffers) {
        if (!d.counter) continue;
        auto cap = graph::eval_scalar(d.counter->capacity, env);
        if (!cap) return cap.error();  // validated at this size already; kept for safety
        CounterReading c;
        c.buffer = d.name;
        c.offset = d.counter->offset;
        c.capacity = static_cast<uint64_t>(*cap);
        counters_.push_back(c);
    }
    if (!counters_.empty())
        counter_readback_ = vk::create_buffer(ctx_, counters_.size() * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    return ok_status();
}

void Executor::record_counter_reads(VkCommandBuffer cb) {
    if (counters_.empty()) return;
    ctx_.set_label("counters");
    BarrierBatch batch;
    std::vector<PhysBuffer*> bufs;
    for (const auto& c : counters_) {
        PhysBuffer* pb = res_.buffers.at(c.buffer).phys[static_cast<size_t>(frame_parity_)].get();
        require(batch, *pb, usage_of(Access::transfer_src, 0));
        bufs.push_back(pb);
    }
    batch.flush(cb);
    for (size_t k = 0; k < counters_.size(); ++k) {
        VkBufferCopy c{counters_[k].offset, k * 4, 4};
        vkCmdCopyBuffer(cb, bufs[k]->buffer.buffer, counter_readback_.buffer, 1, &c);
    }
    transfer_to_host(cb);
}

void Executor::collect_counters() {
    for (size_t k = 0; k < counters_.size(); ++k) {
        CounterReading& c = counters_[k];
        std::memcpy(&c.count, static_cast<const uint8_t*>(counter_readback_.mapped) + k * 4, 4);
        c.frame = frames_rendered_ - 1;
        if (c.peak_frame < 0 || c.count > c.peak) c.peak = c.count, c.peak_frame = c.frame;
        if (c.overflow() && c.overflow_frame < 0) c.overflow_count = c.count, c.overflow_frame = c.frame;
    }
}

} // namespace pl::exec
