// The image viewer: any graph image (a mip, a layer or cube face), read back as float, mapped
// for display on the CPU (channel isolation, exposure, sRGB encoding), uploaded into an RGBA8
// image and blitted over the view in place of the preset's output. CPU mapping keeps the graph untouched: viewing an image adds no pass and no pipeline to
// the preset. (Dear ImGui 1.86's Vulkan backend cannot draw user textures, hence the blit.)
#pragma once

#include "image/image.hpp"
#include "viewer_view.hpp"
#include "vk/resources.hpp"

namespace pl::lab {

struct ViewerMapping {
    int channel = 0;        // 0 = RGB, 1..4 = R, G, B, A shown as grey
    float exposure_ev = 0;  // multiply by 2^ev before display
    bool encode_srgb = true;  // linear data: encode for the display
};

class ViewerTexture {
  public:
    explicit ViewerTexture(vk::Context& ctx) : ctx_(ctx) {}
    ViewerTexture(const ViewerTexture&) = delete;
    ViewerTexture& operator=(const ViewerTexture&) = delete;

    // Maps `src` into the staging buffer; the next record_blit uploads it first.
    void update(const image::Image& src, const ViewerMapping& m);
    // Records the pending upload and a blit into the rectangle `to` of `dst` (TRANSFER_DST,
    // already cleared), placed by `r` (view_rect, relative to `to`) with nearest filtering so
    // magnified texels stay squares.
    void record_blit(VkCommandBuffer cb, VkImage dst, VkRect2D to, const FitRect& r);
    bool ready() const { return uploaded_ || pending_; }
    int width() const { return width_; }
    int height() const { return height_; }

  private:
    void resize(int w, int h);
    void barrier(VkCommandBuffer cb, VkImageLayout to, VkPipelineStageFlags2 src, VkAccessFlags2 sa, VkPipelineStageFlags2 dst,
                 VkAccessFlags2 da);
    vk::Context& ctx_;
    vk::Image image_;
    vk::Buffer staging_;
    int width_ = 0, height_ = 0;
    bool pending_ = false, uploaded_ = false;
    VkImageLayout layout_state_ = VK_IMAGE_LAYOUT_UNDEFINED;
};

} // namespace pl::lab
