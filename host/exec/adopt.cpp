// Executor::adopt_contents: a reload keeps what the old executor's images hold. Rebuilding a
// graph creates every resource anew; without this, a shader edit in a preset that accumulates
// (TAA history, progressive path tracing, simulation state) would start again from black.
#include "exec/barriers.hpp"
#include "exec/executor.hpp"
#include "vk/check.hpp"

namespace pl::exec {

namespace {

// Same shape and same kind of content: copying is meaningful and in bounds.
bool same_shape(const GraphImage& a, const GraphImage& b) {
    const auto& ia = a.phys[0]->image.info();
    const auto& ib = b.phys[0]->image.info();
    return a.format == b.format && a.extent.width == b.extent.width && a.extent.height == b.extent.height &&
           a.extent.depth == b.extent.depth && a.mips == b.mips && a.layers == b.layers && ia.samples == ib.samples &&
           a.history == b.history && ia.type == ib.type;
}

// Images whose contents come from outside the graph are uploaded fresh by create_resources.
bool uploaded(const graph::ImageDesc& d) { return !d.file.empty() || !d.generator.empty(); }

} // namespace

Status Executor::adopt_contents(Executor& old) {
    struct Pair {
        PhysImage *from, *to;
    };
    std::vector<Pair> images;
    for (auto& [name, gi] : res_.images) {
        if (!gi.desc->alias.empty() || uploaded(*gi.desc)) continue;
        auto it = old.res_.images.find(name);
        if (it == old.res_.images.end() || !it->second.desc->alias.empty() || uploaded(*it->second.desc)) continue;
        if (!same_shape(gi, it->second)) continue;
        // Both physical images of a history pair; one for the others (phys[1] null or the same).
        for (size_t k = 0; k < 2; ++k)
            if (gi.phys[k] && it->second.phys[k] && (k == 0 || gi.phys[1] != gi.phys[0]))
                images.push_back({it->second.phys[k].get(), gi.phys[k].get()});
    }
    struct BufferPair {
        PhysBuffer *from, *to;
    };
    std::vector<BufferPair> buffers;
    for (auto& [name, gb] : res_.buffers) {
        auto it = old.res_.buffers.find(name);
        if (it == old.res_.buffers.end()) continue;
        const auto &a = *gb.desc, &b = *it->second.desc;
        // Host-built buffers are built fresh from their meshes, like file and generator images.
        if (!a.generator.empty() || !b.generator.empty()) continue;
        // Initial data from the TOML: a changed array must be seen, so only identical ones carry over.
        if (a.data != b.data || a.data_type != b.data_type || gb.history != it->second.history) continue;
        for (size_t k = 0; k < 2; ++k)
            if (gb.phys[k] && it->second.phys[k] && (k == 0 || gb.phys[1] != gb.phys[0]) &&
                gb.phys[k]->buffer.size == it->second.phys[k]->buffer.size)
                buffers.push_back({it->second.phys[k].get(), gb.phys[k].get()});
    }
    frames_rendered_ = old.frames_rendered_;
    prev_view_proj_ = old.prev_view_proj_;
    // A reload that changes nothing the picture depends on keeps accumulating.
    accum_key_ = old.accum_key_;
    accum_frame_ = old.accum_frame_;
    if (old.prev_camera_view_proj_.size() == prev_camera_view_proj_.size()) prev_camera_view_proj_ = old.prev_camera_view_proj_;
    if (images.empty() && buffers.empty()) return ok_status();

    VK_CHECK(vkResetCommandBuffer(cmd_, 0));
    VkCommandBufferBeginInfo bi{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(cmd_, &bi));
    BarrierBatch batch;
    for (auto& p : images) {
        require(batch, *p.from, usage_of(Access::transfer_src, 0));
        require(batch, *p.to, usage_of(Access::transfer_dst, 0), true);
    }
    for (auto& p : buffers) {
        require(batch, *p.from, usage_of(Access::transfer_src, 0));
        require(batch, *p.to, usage_of(Access::transfer_dst, 0));
    }
    batch.flush(cmd_);
    for (auto& p : images) {
        const auto& info = p.to->image.info();
        std::vector<VkImageCopy> regions;
        for (uint32_t m = 0; m < info.mips; ++m) {
            VkImageSubresourceLayers sub{p.to->image.aspect(), m, 0, info.layers};
            regions.push_back({.srcSubresource = sub,
                               .dstSubresource = sub,
                               .extent = {std::max(1u, info.extent.width >> m), std::max(1u, info.extent.height >> m),
                                          std::max(1u, info.extent.depth >> m)}});
        }
        vkCmdCopyImage(cmd_, p.from->image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, p.to->image.handle(),
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, static_cast<uint32_t>(regions.size()), regions.data());
    }
    for (auto& p : buffers) {
        VkBufferCopy region{0, 0, p.to->buffer.size};
        vkCmdCopyBuffer(cmd_, p.from->buffer.buffer, p.to->buffer.buffer, 1, &region);
    }
    VK_CHECK(vkEndCommandBuffer(cmd_));
    VkSubmitInfo si{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cmd_};
    VK_CHECK(vkQueueSubmit(ctx_.queue(), 1, &si, fence_));
    if (auto w = ctx_.wait(fence_, timeout_, "copying images into the reloaded graph"); !w) return w;
    VkFence f = fence_;
    VK_CHECK(vkResetFences(ctx_.device(), 1, &f));
    return ok_status();
}

} // namespace pl::exec
