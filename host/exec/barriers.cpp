#include "exec/barriers.hpp"

#include <algorithm>

namespace pl::exec {

void BarrierBatch::add(const Barrier& b, VkImage image, const VkImageSubresourceRange& range) {
    images.push_back({.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
                      .srcStageMask = b.src_stages,
                      .srcAccessMask = b.src_access,
                      .dstStageMask = b.dst_stages,
                      .dstAccessMask = b.dst_access,
                      .oldLayout = b.old_layout,
                      .newLayout = b.new_layout,
                      .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                      .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                      .image = image,
                      .subresourceRange = range});
}

void BarrierBatch::add(const Barrier& b, VkBuffer buffer) {
    buffers.push_back({.sType = VK_STRUCTURE_TYPE_BUFFER_MEMORY_BARRIER_2,
                       .srcStageMask = b.src_stages,
                       .srcAccessMask = b.src_access,
                       .dstStageMask = b.dst_stages,
                       .dstAccessMask = b.dst_access,
                       .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                       .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                       .buffer = buffer,
                       .offset = 0,
                       .size = VK_WHOLE_SIZE});
}

void BarrierBatch::flush(VkCommandBuffer cb) {
    if (images.empty() && buffers.empty()) return;
    VkDependencyInfo di{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO,
                        .bufferMemoryBarrierCount = static_cast<uint32_t>(buffers.size()),
                        .pBufferMemoryBarriers = buffers.data(),
                        .imageMemoryBarrierCount = static_cast<uint32_t>(images.size()),
                        .pImageMemoryBarriers = images.data()};
    vkCmdPipelineBarrier2(cb, &di);
    images.clear();
    buffers.clear();
}

void require(BarrierBatch& batch, PhysImage& img, const Usage& usage, bool discard) {
    if (auto b = transition(img.state, usage, discard)) batch.add(*b, img.image.handle(), img.image.full_range());
}

void require(BarrierBatch& batch, PhysBuffer& buf, const Usage& usage) {
    if (auto b = transition(buf.state, usage)) batch.add(*b, buf.buffer.buffer);
}

void record_mip_chain(VkCommandBuffer cb, PhysImage& img, const Usage& final_usage) {
    const auto& info = img.image.info();
    VkImageAspectFlags aspect = img.image.aspect();
    BarrierBatch batch;
    auto range = [&](uint32_t level) { return VkImageSubresourceRange{aspect, level, 1, 0, info.layers}; };
    // Level 0 becomes the first source; the others start as destinations (old contents dropped).
    std::vector<ResourceState> level(info.mips, img.state);
    if (auto b = transition(level[0], usage_of(Access::transfer_src, 0))) batch.add(*b, img.image.handle(), range(0));
    for (uint32_t i = 1; i < info.mips; ++i)
        if (auto b = transition(level[i], usage_of(Access::transfer_dst, 0), true))
            batch.add(*b, img.image.handle(), range(i));
    batch.flush(cb);
    auto dim = [](uint32_t v, uint32_t l) { return static_cast<int32_t>(std::max(1u, v >> l)); };
    for (uint32_t i = 1; i < info.mips; ++i) {
        if (i > 1) {
            if (auto b = transition(level[i - 1], usage_of(Access::transfer_src, 0)))
                batch.add(*b, img.image.handle(), range(i - 1));
            batch.flush(cb);
        }
        VkImageBlit blit{
            .srcSubresource = {aspect, i - 1, 0, info.layers},
            .srcOffsets = {{0, 0, 0}, {dim(info.extent.width, i - 1), dim(info.extent.height, i - 1), dim(info.extent.depth, i - 1)}},
            .dstSubresource = {aspect, i, 0, info.layers},
            .dstOffsets = {{0, 0, 0}, {dim(info.extent.width, i), dim(info.extent.height, i), dim(info.extent.depth, i)}}};
        vkCmdBlitImage(cb, img.image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, img.image.handle(),
                       VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &blit, VK_FILTER_LINEAR);
    }
    // Every level to the final state; the whole-image state then describes all of them.
    for (uint32_t i = 0; i < info.mips; ++i)
        if (auto b = transition(level[i], final_usage)) batch.add(*b, img.image.handle(), range(i));
    batch.flush(cb);
    img.state = level[info.mips - 1];
    // Reads since the last write differ per level; the union keeps later barriers conservative.
    for (const auto& l : level) {
        img.state.read_stages |= l.read_stages;
        img.state.write_stages |= l.write_stages;
        img.state.write_access |= l.write_access;
    }
}

void transfer_to_host(VkCommandBuffer cb) {
    VkMemoryBarrier2 mb{.sType = VK_STRUCTURE_TYPE_MEMORY_BARRIER_2,
                        .srcStageMask = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                        .srcAccessMask = VK_ACCESS_2_TRANSFER_WRITE_BIT,
                        .dstStageMask = VK_PIPELINE_STAGE_2_HOST_BIT,
                        .dstAccessMask = VK_ACCESS_2_HOST_READ_BIT};
    VkDependencyInfo di{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO, .memoryBarrierCount = 1, .pMemoryBarriers = &mb};
    vkCmdPipelineBarrier2(cb, &di);
}

} // namespace pl::exec
