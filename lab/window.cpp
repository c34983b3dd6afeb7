#include "window.hpp"

#include "key_codes.hpp"

#include "image/image.hpp"
#include "vk/barrier.hpp"
#include "vk/check.hpp"

#define GLFW_INCLUDE_VULKAN
#include <GLFW/glfw3.h>

#include <algorithm>
#include <cstdio>

namespace pl::lab {

Result<std::vector<std::string>> init_glfw_and_list_extensions() {
    if (!glfwInit()) {
        Error e = make_error("cannot open a window: no display (passlab run needs X11 or Wayland; "
                             "the headless verbs render, test and check do not)");
        e.code = ExitCode::environment;
        return e;
    }
    uint32_t n = 0;
    const char** names = glfwGetRequiredInstanceExtensions(&n);
    if (!names) {
        Error e = make_error("GLFW found no Vulkan surface support");
        e.code = ExitCode::environment;
        return e;
    }
    return std::vector<std::string>(names, names + n);
}

Result<std::unique_ptr<Window>> Window::create(vk::Context& ctx, int width, int height, const std::string& title,
                                               VkPresentModeKHR mode) {
    std::unique_ptr<Window> w(new Window(ctx));
    glfwWindowHint(GLFW_CLIENT_API, GLFW_NO_API);
    glfwWindowHint(GLFW_SCALE_TO_MONITOR, GLFW_TRUE);  // HiDPI: the framebuffer size decides
    w->window_ = glfwCreateWindow(width, height, title.c_str(), nullptr, nullptr);
    if (!w->window_) {
        Error e = make_error("cannot create a window");
        e.code = ExitCode::environment;
        return e;
    }
    glfwSetWindowUserPointer(w->window_, w.get());
    glfwSetCursorPosCallback(w->window_, [](GLFWwindow* gw, double x, double y) {
        auto* self = static_cast<Window*>(glfwGetWindowUserPointer(gw));
        // Window coordinates to framebuffer pixels (HiDPI scales differ).
        int ww, wh, fw, fh;
        glfwGetWindowSize(gw, &ww, &wh);
        glfwGetFramebufferSize(gw, &fw, &fh);
        double sx = ww > 0 ? double(fw) / ww : 1.0, sy = wh > 0 ? double(fh) / wh : 1.0;
        WindowInput& in = self->input();
        if (in.left) in.drag_dx += x * sx - in.x, in.drag_dy += y * sy - in.y;
        in.x = x * sx;
        in.y = y * sy;
    });
    glfwSetMouseButtonCallback(w->window_, [](GLFWwindow* gw, int button, int action, int) {
        WindowInput& in = static_cast<Window*>(glfwGetWindowUserPointer(gw))->input();
        if (button != GLFW_MOUSE_BUTTON_LEFT) return;
        in.left = action == GLFW_PRESS;
        if (in.left) in.click_x = in.x, in.click_y = in.y;
    });
    glfwSetScrollCallback(w->window_, [](GLFWwindow* gw, double, double dy) {
        static_cast<Window*>(glfwGetWindowUserPointer(gw))->input().scroll += dy;
    });
    glfwSetKeyCallback(w->window_, [](GLFWwindow* gw, int key, int, int action, int) {
        WindowInput& in = static_cast<Window*>(glfwGetWindowUserPointer(gw))->input();
        key_event(in.keys, key, action);
        if (action != GLFW_PRESS && action != GLFW_REPEAT) return;
        if (key == GLFW_KEY_SPACE && action == GLFW_PRESS) in.pause_toggled = true;
        if (key == GLFW_KEY_RIGHT) in.step = true;
        if (key == GLFW_KEY_F12 && action == GLFW_PRESS) in.screenshot = true;
        if (key == GLFW_KEY_TAB && action == GLFW_PRESS) in.toggle_ui = true;
        if (key == GLFW_KEY_F1 && action == GLFW_PRESS) in.toggle_help = true;
        if (key == GLFW_KEY_ESCAPE) glfwSetWindowShouldClose(gw, GLFW_TRUE);
    });
    if (glfwCreateWindowSurface(ctx.instance(), w->window_, nullptr, &w->surface_) != VK_SUCCESS) {
        Error e = make_error("cannot create a Vulkan surface for the window");
        e.code = ExitCode::environment;
        return e;
    }
    VkBool32 supported = VK_FALSE;
    vkGetPhysicalDeviceSurfaceSupportKHR(ctx.physical(), ctx.queue_family(), w->surface_, &supported);
    if (!supported) {
        Error e = make_error("the chosen Vulkan queue cannot present to this window");
        e.code = ExitCode::environment;
        return e;
    }
    w->mode_ = mode;
    VkCommandPoolCreateInfo pci{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                .queueFamilyIndex = ctx.queue_family()};
    VkCommandPool pool;
    VK_CHECK(vkCreateCommandPool(ctx.device(), &pci, nullptr, &pool));
    w->pool_ = vk::UniqueCommandPool(ctx.device(), pool);
    VkCommandBufferAllocateInfo ai{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                   .commandPool = pool,
                                   .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                   .commandBufferCount = 1};
    VK_CHECK(vkAllocateCommandBuffers(ctx.device(), &ai, &w->cmd_));
    VkSemaphoreCreateInfo sci{.sType = VK_STRUCTURE_TYPE_SEMAPHORE_CREATE_INFO};
    VkSemaphore s1, s2;
    VK_CHECK(vkCreateSemaphore(ctx.device(), &sci, nullptr, &s1));
    VK_CHECK(vkCreateSemaphore(ctx.device(), &sci, nullptr, &s2));
    w->acquired_ = vk::UniqueSemaphore(ctx.device(), s1);
    w->rendered_ = vk::UniqueSemaphore(ctx.device(), s2);
    VkFenceCreateInfo fci{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence f;
    VK_CHECK(vkCreateFence(ctx.device(), &fci, nullptr, &f));
    w->fence_ = vk::UniqueFence(ctx.device(), f);
    if (auto s = w->create_swapchain(); !s) return s.error();
    return w;
}

Window::~Window() {
    if (ctx_.device() && !ctx_.hung()) vkDeviceWaitIdle(ctx_.device());
    destroy_swapchain();
    if (surface_) vkDestroySurfaceKHR(ctx_.instance(), surface_, nullptr);
    if (window_) glfwDestroyWindow(window_);
}

void Window::destroy_swapchain() {
    framebuffers_.clear();
    views_.clear();
    if (swapchain_) vkDestroySwapchainKHR(ctx_.device(), swapchain_, nullptr);
    swapchain_ = VK_NULL_HANDLE;
    images_.clear();
}

Status Window::create_swapchain() {
    VkSurfaceCapabilitiesKHR caps;
    VK_CHECK(vkGetPhysicalDeviceSurfaceCapabilitiesKHR(ctx_.physical(), surface_, &caps));
    int fw = 0, fh = 0;
    glfwGetFramebufferSize(window_, &fw, &fh);
    extent_ = caps.currentExtent.width != UINT32_MAX
                  ? caps.currentExtent
                  : VkExtent2D{std::clamp(static_cast<uint32_t>(fw), caps.minImageExtent.width, caps.maxImageExtent.width),
                               std::clamp(static_cast<uint32_t>(fh), caps.minImageExtent.height, caps.maxImageExtent.height)};
    if (extent_.width == 0 || extent_.height == 0) return ok_status();  // minimised
    uint32_t n = 0;
    vkGetPhysicalDeviceSurfaceFormatsKHR(ctx_.physical(), surface_, &n, nullptr);
    std::vector<VkSurfaceFormatKHR> formats(n);
    vkGetPhysicalDeviceSurfaceFormatsKHR(ctx_.physical(), surface_, &n, formats.data());
    // The output image holds display-ready values (sRGB-encoded when it is rgba8_srgb), and a
    // blit copies them: a UNORM swapchain presents them unchanged.
    VkSurfaceFormatKHR chosen = formats.at(0);
    for (const auto& f : formats)
        if (f.format == VK_FORMAT_B8G8R8A8_UNORM || f.format == VK_FORMAT_R8G8B8A8_UNORM) chosen = f;
    format_ = chosen.format;
    uint32_t pm_n = 0;
    vkGetPhysicalDeviceSurfacePresentModesKHR(ctx_.physical(), surface_, &pm_n, nullptr);
    std::vector<VkPresentModeKHR> modes(pm_n);
    vkGetPhysicalDeviceSurfacePresentModesKHR(ctx_.physical(), surface_, &pm_n, modes.data());
    VkPresentModeKHR mode = std::find(modes.begin(), modes.end(), mode_) != modes.end() ? mode_ : VK_PRESENT_MODE_FIFO_KHR;
    VkSwapchainCreateInfoKHR sci{.sType = VK_STRUCTURE_TYPE_SWAPCHAIN_CREATE_INFO_KHR,
                                 .surface = surface_,
                                 .minImageCount = std::max(caps.minImageCount, 2u),
                                 .imageFormat = chosen.format,
                                 .imageColorSpace = chosen.colorSpace,
                                 .imageExtent = extent_,
                                 .imageArrayLayers = 1,
                                 .imageUsage = VK_IMAGE_USAGE_TRANSFER_DST_BIT | VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT |
                                               (caps.supportedUsageFlags & VK_IMAGE_USAGE_TRANSFER_SRC_BIT),
                                 .imageSharingMode = VK_SHARING_MODE_EXCLUSIVE,
                                 .preTransform = caps.currentTransform,
                                 .compositeAlpha = VK_COMPOSITE_ALPHA_OPAQUE_BIT_KHR,
                                 .presentMode = mode,
                                 .clipped = VK_TRUE,
                                 .oldSwapchain = swapchain_};
    VkSwapchainKHR sc;
    VK_CHECK(vkCreateSwapchainKHR(ctx_.device(), &sci, nullptr, &sc));
    destroy_swapchain();
    swapchain_ = sc;
    uint32_t count = 0;
    vkGetSwapchainImagesKHR(ctx_.device(), swapchain_, &count, nullptr);
    images_.resize(count);
    vkGetSwapchainImagesKHR(ctx_.device(), swapchain_, &count, images_.data());
    if (!render_pass_)
        if (auto s = create_render_pass(); !s) return s;
    for (VkImage image : images_) {
        VkImageViewCreateInfo vci{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                  .image = image,
                                  .viewType = VK_IMAGE_VIEW_TYPE_2D,
                                  .format = format_,
                                  .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}};
        VkImageView view;
        VK_CHECK(vkCreateImageView(ctx_.device(), &vci, nullptr, &view));
        views_.emplace_back(ctx_.device(), view);
        VkFramebufferCreateInfo fci{.sType = VK_STRUCTURE_TYPE_FRAMEBUFFER_CREATE_INFO,
                                    .renderPass = render_pass_,
                                    .attachmentCount = 1,
                                    .pAttachments = &view,
                                    .width = extent_.width,
                                    .height = extent_.height,
                                    .layers = 1};
        VkFramebuffer fb;
        VK_CHECK(vkCreateFramebuffer(ctx_.device(), &fci, nullptr, &fb));
        framebuffers_.emplace_back(ctx_.device(), fb);
    }
    return ok_status();
}

// One subpass that loads the blitted frame and draws the overlay on top; it also performs the
// final transition to PRESENT_SRC. A classic render pass (not dynamic rendering) because Dear
// ImGui 1.86's Vulkan backend wants one at initialisation.
Status Window::create_render_pass() {
    VkAttachmentDescription att{.format = format_,
                                .samples = VK_SAMPLE_COUNT_1_BIT,
                                .loadOp = VK_ATTACHMENT_LOAD_OP_LOAD,
                                .storeOp = VK_ATTACHMENT_STORE_OP_STORE,
                                .stencilLoadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE,
                                .stencilStoreOp = VK_ATTACHMENT_STORE_OP_DONT_CARE,
                                .initialLayout = VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL,
                                .finalLayout = VK_IMAGE_LAYOUT_PRESENT_SRC_KHR};
    VkAttachmentReference ref{0, VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL};
    VkSubpassDescription sub{.pipelineBindPoint = VK_PIPELINE_BIND_POINT_GRAPHICS, .colorAttachmentCount = 1, .pColorAttachments = &ref};
    // The blit (transfer write) must land before the overlay blends over it.
    VkSubpassDependency dep{.srcSubpass = VK_SUBPASS_EXTERNAL,
                            .dstSubpass = 0,
                            .srcStageMask = VK_PIPELINE_STAGE_TRANSFER_BIT,
                            .dstStageMask = VK_PIPELINE_STAGE_COLOR_ATTACHMENT_OUTPUT_BIT,
                            .srcAccessMask = VK_ACCESS_TRANSFER_WRITE_BIT,
                            .dstAccessMask = VK_ACCESS_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_COLOR_ATTACHMENT_WRITE_BIT};
    VkRenderPassCreateInfo rci{.sType = VK_STRUCTURE_TYPE_RENDER_PASS_CREATE_INFO,
                               .attachmentCount = 1,
                               .pAttachments = &att,
                               .subpassCount = 1,
                               .pSubpasses = &sub,
                               .dependencyCount = 1,
                               .pDependencies = &dep};
    VkRenderPass rp;
    VK_CHECK(vkCreateRenderPass(ctx_.device(), &rci, nullptr, &rp));
    render_pass_ = vk::UniqueRenderPass(ctx_.device(), rp);
    return ok_status();
}

void Window::save_capture() {
    image::Image img;
    img.width = static_cast<int>(extent_.width);
    img.height = static_cast<int>(extent_.height);
    img.pixels.resize(size_t(img.width) * img.height * 4);
    const auto* px = static_cast<const uint8_t*>(capture_buffer_.mapped);
    const bool bgra = format_ == VK_FORMAT_B8G8R8A8_UNORM || format_ == VK_FORMAT_B8G8R8A8_SRGB;
    for (size_t i = 0; i < size_t(img.width) * img.height; ++i) {
        for (int c = 0; c < 3; ++c) img.pixels[i * 4 + c] = px[i * 4 + (bgra ? 2 - c : c)] / 255.0f;
        img.pixels[i * 4 + 3] = 1.0f;
    }
    if (auto s = image::save_image(img, capture_file_); s) std::fprintf(stderr, "passlab: window captured to %s\n", capture_file_.c_str());
    else std::fprintf(stderr, "passlab: window capture failed: %s\n", s.error().message.c_str()), capture_failed_ = true;
    capture_file_.clear();
    capture_buffer_ = {};
}

std::array<int, 2> Window::framebuffer_size() const {
    int w = 0, h = 0;
    glfwGetFramebufferSize(window_, &w, &h);
    return {w, h};
}

float Window::content_scale() const {
    float x = 1, y = 1;
    glfwGetWindowContentScale(window_, &x, &y);
    return std::max(x, y);
}

bool Window::should_close() const { return glfwWindowShouldClose(window_); }
void Window::poll() { glfwPollEvents(); }
void Window::set_title(const std::string& t) { glfwSetWindowTitle(window_, t.c_str()); }

WindowInput Window::take_input() {
    WindowInput out = input_;
    input_.drag_dx = input_.drag_dy = input_.scroll = 0;
    input_.pause_toggled = input_.step = input_.screenshot = input_.toggle_ui = input_.toggle_help = false;
    input_.keys.clear(exec::KeyboardState::pressed);  // one frame sees a press
    return out;
}

Status Window::present(const Recorders& rec) {
    if (!swapchain_) {
        if (auto s = create_swapchain(); !s || !swapchain_) return s;
    }
    uint32_t index = 0;
    VkResult r = vkAcquireNextImageKHR(ctx_.device(), swapchain_, UINT64_MAX, acquired_, VK_NULL_HANDLE, &index);
    if (r == VK_ERROR_OUT_OF_DATE_KHR) {
        vkDeviceWaitIdle(ctx_.device());
        return create_swapchain();
    }
    if (r != VK_SUBOPTIMAL_KHR) VK_CHECK(r);
    VK_CHECK(vkResetCommandBuffer(cmd_, 0));
    VkCommandBufferBeginInfo bi{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(cmd_, &bi));
    // The swapchain image is outside the graph: its two transitions are the window's own.
    auto barrier = [&](VkImageLayout from, VkImageLayout to, VkPipelineStageFlags2 src, VkAccessFlags2 sa,
                       VkPipelineStageFlags2 dst, VkAccessFlags2 da) {
        vk::image_barrier(cmd_, images_[index], {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1}, from, to, src, sa, dst, da);
    };
    barrier(VK_IMAGE_LAYOUT_UNDEFINED, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, 0,
            VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    VkClearColorValue black{};
    VkImageSubresourceRange range{VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    vkCmdClearColorImage(cmd_, images_[index], VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &black, 1, &range);
    barrier(VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
            VK_ACCESS_2_TRANSFER_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_WRITE_BIT);
    Status st = rec.blit ? rec.blit(cmd_, images_[index], extent_) : ok_status();
    VkRenderPassBeginInfo rbi{.sType = VK_STRUCTURE_TYPE_RENDER_PASS_BEGIN_INFO,
                              .renderPass = render_pass_,
                              .framebuffer = framebuffers_[index],
                              .renderArea = {{0, 0}, extent_}};
    vkCmdBeginRenderPass(cmd_, &rbi, VK_SUBPASS_CONTENTS_INLINE);
    if (rec.overlay) rec.overlay(cmd_);
    vkCmdEndRenderPass(cmd_);
    bool capture = !capture_file_.empty();
    if (capture) {
        // Read the finished frame back: PRESENT_SRC -> TRANSFER_SRC, copy, and back.
        capture_buffer_ = vk::create_buffer(ctx_, VkDeviceSize(extent_.width) * extent_.height * 4, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
        barrier(VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, VK_ACCESS_2_TRANSFER_READ_BIT);
        VkBufferImageCopy region{.imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1}, .imageExtent = {extent_.width, extent_.height, 1}};
        vkCmdCopyImageToBuffer(cmd_, images_[index], VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, capture_buffer_.buffer, 1, &region);
        barrier(VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_IMAGE_LAYOUT_PRESENT_SRC_KHR, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT, 0,
                VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT, 0);
    }
    VK_CHECK(vkEndCommandBuffer(cmd_));
    // The first use of the acquired image is the transfer (clear, blit); the overlay's
    // attachment access is ordered after it by the render pass dependency.
    VkPipelineStageFlags wait_stage = VK_PIPELINE_STAGE_TRANSFER_BIT;
    VkSemaphore wait = acquired_, signal = rendered_;
    VkSubmitInfo si{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO,
                    .waitSemaphoreCount = 1,
                    .pWaitSemaphores = &wait,
                    .pWaitDstStageMask = &wait_stage,
                    .commandBufferCount = 1,
                    .pCommandBuffers = &cmd_,
                    .signalSemaphoreCount = 1,
                    .pSignalSemaphores = &signal};
    VkFence f = fence_;
    VK_CHECK(vkQueueSubmit(ctx_.queue(), 1, &si, f));
    VkPresentInfoKHR pi{.sType = VK_STRUCTURE_TYPE_PRESENT_INFO_KHR,
                        .waitSemaphoreCount = 1,
                        .pWaitSemaphores = &signal,
                        .swapchainCount = 1,
                        .pSwapchains = &swapchain_,
                        .pImageIndices = &index};
    r = vkQueuePresentKHR(ctx_.queue(), &pi);
    if (auto w = ctx_.wait(f, std::chrono::seconds(20), "present"); !w) return w;
    VK_CHECK(vkResetFences(ctx_.device(), 1, &f));
    if (capture) save_capture();
    if (r == VK_ERROR_OUT_OF_DATE_KHR || r == VK_SUBOPTIMAL_KHR) {
        vkDeviceWaitIdle(ctx_.device());
        if (auto s = create_swapchain(); !s) return s;
    } else {
        VK_CHECK(r);
    }
    return st;
}

} // namespace pl::lab
