#include "viewer.hpp"

#include "vk/barrier.hpp"
#include "vk/check.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <vector>

namespace pl::lab {

void ViewerTexture::resize(int w, int h) {
    vk::ImageInfo info;
    info.format = VK_FORMAT_R8G8B8A8_UNORM;
    info.extent = {static_cast<uint32_t>(w), static_cast<uint32_t>(h), 1};
    info.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
    // The previous image is used by a frame only until the window's fence wait, which every
    // frame ends with: replacing it here is safe.
    image_ = vk::Image(ctx_, info);
    staging_ = vk::create_buffer(ctx_, static_cast<VkDeviceSize>(w) * h * 4, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
    width_ = w;
    height_ = h;
    layout_state_ = VK_IMAGE_LAYOUT_UNDEFINED;
    uploaded_ = false;
}

void ViewerTexture::update(const image::Image& src, const ViewerMapping& m) {
    if (src.width <= 0 || src.height <= 0) return;
    if (src.width != width_ || src.height != height_) resize(src.width, src.height);
    const float gain = std::exp2(m.exposure_ev);
    auto to8 = [&](float v) {
        if (!std::isfinite(v)) return uint8_t(255);  // NaN/Inf stand out as full white
        v = std::max(0.0f, v * gain);
        if (m.encode_srgb) v = image::linear_to_srgb(std::min(v, 1.0f));
        return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f));
    };
    auto* out = static_cast<uint8_t*>(staging_.mapped);
    for (int y = 0; y < height_; ++y)
        for (int x = 0; x < width_; ++x) {
            const float* p = src.at(x, y);
            uint8_t* o = out + (static_cast<size_t>(y) * width_ + x) * 4;
            if (m.channel == 0) {
                for (int c = 0; c < 3; ++c) o[c] = to8(p[c]);
            } else {
                // Alpha is coverage/opacity, not light: shown without exposure or encoding.
                float v = p[m.channel - 1];
                uint8_t g = m.channel == 4 ? static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)) : to8(v);
                o[0] = o[1] = o[2] = g;
            }
            o[3] = 255;
        }
    pending_ = true;
}

void ViewerTexture::barrier(VkCommandBuffer cb, VkImageLayout to, VkPipelineStageFlags2 src, VkAccessFlags2 sa,
                            VkPipelineStageFlags2 dst, VkAccessFlags2 da) {
    vk::image_barrier(cb, image_.handle(), image_.full_range(), layout_state_, to, src, sa, dst, da);
    layout_state_ = to;
}

void ViewerTexture::record_blit(VkCommandBuffer cb, VkImage dst, VkRect2D to, const FitRect& r) {
    constexpr auto transfer = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
    if (pending_) {
        barrier(cb, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, transfer, 0, transfer, VK_ACCESS_2_TRANSFER_WRITE_BIT);
        VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                                 .imageExtent = {static_cast<uint32_t>(width_), static_cast<uint32_t>(height_), 1}};
        vkCmdCopyBufferToImage(cb, staging_.buffer, image_.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &region);
        pending_ = false;
        uploaded_ = true;
    }
    if (!uploaded_) return;
    barrier(cb, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, transfer, VK_ACCESS_2_TRANSFER_WRITE_BIT, transfer, VK_ACCESS_2_TRANSFER_READ_BIT);
    // Only what falls inside the view: blit rectangles must lie within both images.
    std::vector<VkImageBlit> blits;
    for (const BlitRegion& b : blit_regions(r, width_, height_, static_cast<int>(to.extent.width), static_cast<int>(to.extent.height)))
        blits.push_back({.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                         .srcOffsets = {{b.sx0, b.sy0, 0}, {b.sx1, b.sy1, 1}},
                         .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                         .dstOffsets = {{to.offset.x + b.dx0, to.offset.y + b.dy0, 0}, {to.offset.x + b.dx1, to.offset.y + b.dy1, 1}}});
    if (blits.empty()) return;
    vkCmdBlitImage(cb, image_.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                   static_cast<uint32_t>(blits.size()), blits.data(),
                   VK_FILTER_NEAREST);
}

} // namespace pl::lab
