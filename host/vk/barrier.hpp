// One image layout transition recorded on its own, for images outside a graph (swapchain
// images, the live lab's viewer texture). Graph resources never use this: their barriers are
// derived by the planner (exec/plan.hpp).
#pragma once

#include <vulkan/vulkan.h>

namespace pl::vk {

inline void image_barrier(VkCommandBuffer cb, VkImage image, const VkImageSubresourceRange& range, VkImageLayout from,
                          VkImageLayout to, VkPipelineStageFlags2 src_stage, VkAccessFlags2 src_access,
                          VkPipelineStageFlags2 dst_stage, VkAccessFlags2 dst_access) {
    VkImageMemoryBarrier2 ib{.sType = VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2,
                             .srcStageMask = src_stage,
                             .srcAccessMask = src_access,
                             .dstStageMask = dst_stage,
                             .dstAccessMask = dst_access,
                             .oldLayout = from,
                             .newLayout = to,
                             .srcQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                             .dstQueueFamilyIndex = VK_QUEUE_FAMILY_IGNORED,
                             .image = image,
                             .subresourceRange = range};
    VkDependencyInfo di{.sType = VK_STRUCTURE_TYPE_DEPENDENCY_INFO, .imageMemoryBarrierCount = 1, .pImageMemoryBarriers = &ib};
    vkCmdPipelineBarrier2(cb, &di);
}

} // namespace pl::vk
