// Move-only owner of one device-level Vulkan handle (pipeline, image view, memory ...): the
// destroy call is part of the type, so no object is ever destroyed by a hand-kept list.
#pragma once

#include <vulkan/vulkan.h>

#include <utility>

namespace pl::vk {

template <class H, void (*Destroy)(VkDevice, H, const VkAllocationCallbacks*)> class Unique {
  public:
    Unique() = default;
    Unique(VkDevice device, H handle) : device_(device), handle_(handle) {}
    Unique(const Unique&) = delete;
    Unique& operator=(const Unique&) = delete;
    Unique(Unique&& o) noexcept : device_(o.device_), handle_(std::exchange(o.handle_, H{})) {}
    Unique& operator=(Unique&& o) noexcept {
        if (this != &o) {
            reset();
            device_ = o.device_;
            handle_ = std::exchange(o.handle_, H{});
        }
        return *this;
    }
    ~Unique() { reset(); }

    void reset() {
        if (handle_ != H{}) Destroy(device_, handle_, nullptr);
        handle_ = H{};
    }
    // Gives up ownership without destroying (for objects a hung GPU may still use).
    H release() { return std::exchange(handle_, H{}); }
    H get() const { return handle_; }
    operator H() const { return handle_; }
    explicit operator bool() const { return handle_ != H{}; }

  private:
    VkDevice device_ = VK_NULL_HANDLE;
    H handle_{};
};

// vkDestroy* functions are loader trampolines; wrapping them keeps the template argument a
// plain function pointer.
// clang-format off
using UniqueBuffer = Unique<VkBuffer, vkDestroyBuffer>;
using UniqueImage = Unique<VkImage, vkDestroyImage>;
using UniqueImageView = Unique<VkImageView, vkDestroyImageView>;
using UniqueSampler = Unique<VkSampler, vkDestroySampler>;
using UniqueMemory = Unique<VkDeviceMemory, vkFreeMemory>;
using UniquePipeline = Unique<VkPipeline, vkDestroyPipeline>;
using UniquePipelineLayout = Unique<VkPipelineLayout, vkDestroyPipelineLayout>;
using UniqueSetLayout = Unique<VkDescriptorSetLayout, vkDestroyDescriptorSetLayout>;
using UniqueDescriptorPool = Unique<VkDescriptorPool, vkDestroyDescriptorPool>;
using UniqueShaderModule = Unique<VkShaderModule, vkDestroyShaderModule>;
using UniqueCommandPool = Unique<VkCommandPool, vkDestroyCommandPool>;
using UniqueFence = Unique<VkFence, vkDestroyFence>;
using UniqueSemaphore = Unique<VkSemaphore, vkDestroySemaphore>;
using UniqueQueryPool = Unique<VkQueryPool, vkDestroyQueryPool>;
using UniqueRenderPass = Unique<VkRenderPass, vkDestroyRenderPass>;
using UniqueFramebuffer = Unique<VkFramebuffer, vkDestroyFramebuffer>;
// clang-format on

} // namespace pl::vk
