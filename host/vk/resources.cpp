#include "vk/resources.hpp"

#include "vk/check.hpp"
#include "vk/formats.hpp"

namespace pl::vk {

Buffer create_buffer(Context& ctx, VkDeviceSize size, VkBufferUsageFlags usage, bool host_visible) {
    Buffer b;
    b.size = size;
    VkBufferCreateInfo bci{.sType = VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO,
                           .size = size,
                           .usage = usage,
                           .sharingMode = VK_SHARING_MODE_EXCLUSIVE};
    VkBuffer buf;
    VK_CHECK(vkCreateBuffer(ctx.device(), &bci, nullptr, &buf));
    b.buffer = UniqueBuffer(ctx.device(), buf);
    VkMemoryRequirements req;
    vkGetBufferMemoryRequirements(ctx.device(), buf, &req);
    VkMemoryPropertyFlags want = host_visible ? (VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT |
                                                 VK_MEMORY_PROPERTY_HOST_COHERENT_BIT)
                                              : VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT;
    VkMemoryAllocateInfo mai{.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                             .allocationSize = req.size,
                             .memoryTypeIndex = ctx.memory_type(req.memoryTypeBits, want)};
    VkDeviceMemory mem;
    VK_CHECK(vkAllocateMemory(ctx.device(), &mai, nullptr, &mem));
    b.memory = UniqueMemory(ctx.device(), mem);
    VK_CHECK(vkBindBufferMemory(ctx.device(), buf, mem, 0));
    if (host_visible) VK_CHECK(vkMapMemory(ctx.device(), mem, 0, VK_WHOLE_SIZE, 0, &b.mapped));
    return b;
}

VkImageAspectFlags aspect_of(VkFormat f) {
    const FormatInfo* fi = find_format(f);
    if (fi && fi->is_depth)
        return VK_IMAGE_ASPECT_DEPTH_BIT | (fi->has_stencil ? VK_IMAGE_ASPECT_STENCIL_BIT : 0);
    return VK_IMAGE_ASPECT_COLOR_BIT;
}

Image::Image(Context& ctx, const ImageInfo& info) : device_(ctx.device()), info_(info) {
    aspect_ = aspect_of(info.format);
    VkImageCreateInfo ici{.sType = VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO,
                          .flags = info.cube ? static_cast<VkImageCreateFlags>(VK_IMAGE_CREATE_CUBE_COMPATIBLE_BIT) : 0u,
                          .imageType = info.type,
                          .format = info.format,
                          .extent = info.extent,
                          .mipLevels = info.mips,
                          .arrayLayers = info.layers,
                          .samples = info.samples,
                          .tiling = VK_IMAGE_TILING_OPTIMAL,
                          .usage = info.usage,
                          .sharingMode = VK_SHARING_MODE_EXCLUSIVE,
                          .initialLayout = VK_IMAGE_LAYOUT_UNDEFINED};
    // 3D images rendered slice by slice need 2D-array-compatible views.
    if (info.type == VK_IMAGE_TYPE_3D && (info.usage & VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT))
        ici.flags |= VK_IMAGE_CREATE_2D_ARRAY_COMPATIBLE_BIT;
    VkImage img;
    VK_CHECK(vkCreateImage(device_, &ici, nullptr, &img));
    image_ = UniqueImage(device_, img);
    VkMemoryRequirements req;
    vkGetImageMemoryRequirements(device_, img, &req);
    VkMemoryAllocateInfo mai{.sType = VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO,
                             .allocationSize = req.size,
                             .memoryTypeIndex = ctx.memory_type(req.memoryTypeBits,
                                                                VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT)};
    VkDeviceMemory mem;
    VK_CHECK(vkAllocateMemory(device_, &mai, nullptr, &mem));
    memory_ = UniqueMemory(device_, mem);
    VK_CHECK(vkBindImageMemory(device_, img, mem, 0));

    // The sampled view shows depth only: a combined depth/stencil view is not sampleable.
    VkImageAspectFlags view_aspect =
        (aspect_ & VK_IMAGE_ASPECT_DEPTH_BIT) ? static_cast<VkImageAspectFlags>(VK_IMAGE_ASPECT_DEPTH_BIT) : aspect_;
    if (info.usage & (VK_IMAGE_USAGE_SAMPLED_BIT | VK_IMAGE_USAGE_STORAGE_BIT |
                      VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT | VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT)) {
        VkImageViewCreateInfo vci{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                  .image = img,
                                  .viewType = info.view_type,
                                  .format = info.format,
                                  .subresourceRange = {view_aspect, 0, info.mips, 0, info.layers}};
        VkImageView v;
        VK_CHECK(vkCreateImageView(device_, &vci, nullptr, &v));
        view_ = UniqueImageView(device_, v);
    }
}

VkImageView Image::attachment_view(uint32_t mip, int layer) {
    auto key = std::make_pair(mip, layer);
    auto it = sub_views_.find(key);
    if (it != sub_views_.end()) return it->second;
    bool is3d = info_.type == VK_IMAGE_TYPE_3D;
    uint32_t nlayers = is3d ? info_.extent.depth : info_.layers;
    VkImageViewCreateInfo vci{
        .sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
        .image = image_,
        .viewType = layer < 0 ? VK_IMAGE_VIEW_TYPE_2D_ARRAY : VK_IMAGE_VIEW_TYPE_2D,
        .format = info_.format,
        .subresourceRange = {aspect_, mip, 1, layer < 0 ? 0u : static_cast<uint32_t>(layer),
                             layer < 0 ? nlayers : 1u}};
    VkImageView v;
    VK_CHECK(vkCreateImageView(device_, &vci, nullptr, &v));
    return sub_views_.emplace(key, UniqueImageView(device_, v)).first->second;
}

VkImageView Image::sub_view(VkImageViewType type, uint32_t mip, uint32_t mips, uint32_t layer, uint32_t layers) {
    auto key = std::make_tuple(static_cast<int>(type), mip, mips, layer, layers);
    auto it = range_views_.find(key);
    if (it != range_views_.end()) return it->second;
    VkImageAspectFlags a = (aspect_ & VK_IMAGE_ASPECT_DEPTH_BIT) ? static_cast<VkImageAspectFlags>(VK_IMAGE_ASPECT_DEPTH_BIT) : aspect_;
    VkImageViewCreateInfo vci{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                              .image = image_,
                              .viewType = type,
                              .format = info_.format,
                              .subresourceRange = {a, mip, mips, layer, layers}};
    VkImageView v;
    VK_CHECK(vkCreateImageView(device_, &vci, nullptr, &v));
    return range_views_.emplace(key, UniqueImageView(device_, v)).first->second;
}

} // namespace pl::vk
