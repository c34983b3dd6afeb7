// Buffers, images and samplers with their memory, each a move-only owner. One allocation per
// resource: graphs hold tens of resources, not thousands, so a sub-allocator would buy nothing.
#pragma once

#include "vk/context.hpp"
#include "vk/unique.hpp"

#include <map>
#include <tuple>
#include <utility>

namespace pl::vk {

struct Buffer {
    UniqueBuffer buffer;
    UniqueMemory memory;
    VkDeviceSize size = 0;
    void* mapped = nullptr;  // host-visible buffers stay mapped
};

// Host-visible buffers are coherent and persistently mapped (uniforms, staging, readback).
Buffer create_buffer(Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, bool host_visible);

struct ImageInfo {
    VkImageType type = VK_IMAGE_TYPE_2D;
    VkImageViewType view_type = VK_IMAGE_VIEW_TYPE_2D;
    VkFormat format = VK_FORMAT_R8G8B8A8_UNORM;
    VkExtent3D extent{1, 1, 1};
    uint32_t mips = 1, layers = 1;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    VkImageUsageFlags usage = 0;
    bool cube = false;
};

class Image {
  public:
    Image() = default;
    Image(Context& ctx, const ImageInfo& info);
    Image(Image&&) noexcept = default;
    Image& operator=(Image&&) noexcept = default;

    VkImage handle() const { return image_; }
    const ImageInfo& info() const { return info_; }
    VkImageAspectFlags aspect() const { return aspect_; }
    // The whole image (all mips and layers) with the image's view type, for sampling/storage.
    VkImageView view() const { return view_; }
    // A 2D (or 2D-array when layer < 0) view of one mip level, for attachments and per-mip
    // storage; created on first use.
    VkImageView attachment_view(uint32_t mip, int layer);
    // A view of levels [mip, mip + mips) and layers [layer, layer + layers) of type `type`, for
    // sampling or storage (the depth aspect only, for depth formats); created on first use. A
    // sampled view of one level makes that level the shader's lod 0.
    VkImageView sub_view(VkImageViewType type, uint32_t mip, uint32_t mips, uint32_t layer, uint32_t layers);
    VkImageSubresourceRange full_range() const {
        return {aspect_, 0, info_.mips, 0, info_.layers};
    }

  private:
    VkDevice device_ = VK_NULL_HANDLE;
    ImageInfo info_;
    VkImageAspectFlags aspect_ = VK_IMAGE_ASPECT_COLOR_BIT;
    UniqueImage image_;
    UniqueMemory memory_;
    UniqueImageView view_;
    std::map<std::pair<uint32_t, int>, UniqueImageView> sub_views_;
    std::map<std::tuple<int, uint32_t, uint32_t, uint32_t, uint32_t>, UniqueImageView> range_views_;
};

VkImageAspectFlags aspect_of(VkFormat f);

} // namespace pl::vk
