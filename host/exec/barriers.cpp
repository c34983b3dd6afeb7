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
    require(batch, img, img.state.all(), usage, discard);
}

void require(BarrierBatch& batch, PhysImage& img, const SubRange& range, const Usage& usage, bool discard) {
    for (const auto& rb : transition(img.state, range, usage, discard))
        batch.add(rb.barrier, img.image.handle(),
                  {img.image.aspect(), rb.range.mip, rb.range.mips, rb.range.layer, rb.range.layers});
}

void require(BarrierBatch& batch, PhysBuffer& buf, const Usage& usage) {
    if (auto b = transition(buf.state, usage)) batch.add(*b, buf.buffer.buffer);
}

void record_mip_chain(VkCommandBuffer cb, PhysImage& img, const Usage& final_usage) {
    const auto& info = img.image.info();
    VkImageAspectFlags aspect = img.image.aspect();
    BarrierBatch batch;
    auto level = [&](uint32_t l) { return SubRange{l, 1, 0, info.layers}; };
    // Level 0 becomes the first source; the others start as destinations (old contents dropped).
    require(batch, img, level(0), usage_of(Access::transfer_src, 0));
    require(batch, img, {1, info.mips - 1, 0, info.layers}, usage_of(Access::transfer_dst, 0), true);
    batch.flush(cb);
    auto dim = [](uint32_t v, uint32_t l) { return static_cast<int32_t>(std::max(1u, v >> l)); };
    for (uint32_t i = 1; i < info.mips; ++i) {
        if (i > 1) {
            require(batch, img, level(i - 1), usage_of(Access::transfer_src, 0));
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
    // Every level to the final state (levels that ended in the same state share one barrier).
    require(batch, img, img.state.all(), final_usage);
    batch.flush(cb);
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
