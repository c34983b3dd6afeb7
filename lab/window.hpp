// The live lab's window: a GLFW window with a Vulkan surface and swapchain. Only `passlab run`
// creates one; headless verbs never initialise GLFW.
#pragma once

#include "exec/keyboard.hpp"
#include "util/error.hpp"
#include "vk/context.hpp"
#include "vk/resources.hpp"

#include <array>
#include <functional>
#include <memory>
#include <string>
#include <vector>

struct GLFWwindow;

namespace pl::lab {

// GLFW must be initialised before the Vulkan instance so it can name the surface extensions.
Result<std::vector<std::string>> init_glfw_and_list_extensions();

// Mouse and keyboard state gathered from GLFW callbacks, in framebuffer pixels.
struct WindowInput {
    double x = 0, y = 0;                // cursor
    bool left = false;                  // left button held
    double click_x = 0, click_y = 0;    // where the left button last went down
    double drag_dx = 0, drag_dy = 0;    // cursor motion while held, since the last take()
    double scroll = 0;                  // wheel steps since the last take()
    bool pause_toggled = false, step = false, screenshot = false, toggle_ui = false, toggle_help = false;
    exec::KeyboardState keys;          // frame.keys (Shadertoy's keyboard texture); `pressed` consumed by take()
};

class Window {
  public:
    static Result<std::unique_ptr<Window>> create(vk::Context& ctx, int width, int height, const std::string& title,
                                                  VkPresentModeKHR mode);
    ~Window();

    bool should_close() const;
    void poll();
    // What a frame records into the swapchain image's command buffer.
    struct Recorders {
        // Fills the image, which arrives cleared in TRANSFER_DST layout (the graph's output blit).
        std::function<Status(VkCommandBuffer, VkImage, VkExtent2D)> blit;
        // Draws inside a render pass over the image that loads its contents (the UI).
        std::function<void(VkCommandBuffer)> overlay;
    };
    // Acquires a swapchain image, records the frame, presents. Recreates the swapchain when the
    // window size changed.
    Status present(const Recorders& r);
    // The render pass the overlay draws in (fixed for the window's life) and swapchain facts the
    // UI backend needs.
    VkRenderPass render_pass() const { return render_pass_; }
    uint32_t image_count() const { return static_cast<uint32_t>(images_.size()); }
    // The framebuffer size in pixels (HiDPI: larger than the window size in screen units).
    std::array<int, 2> framebuffer_size() const;
    float content_scale() const;
    GLFWwindow* handle() const { return window_; }
    void set_title(const std::string& t);
    // Saves the next presented frame, overlay included, as a PNG (UI screenshots, tests).
    void capture_next(const std::string& png) { capture_file_ = png; }
    bool capture_failed() const { return capture_failed_; }  // a --capture that was not written
    // The input since the last call (motion, wheel and key presses are consumed).
    WindowInput take_input();
    WindowInput& input() { return input_; }

  private:
    Window(vk::Context& ctx) : ctx_(ctx) {}
    Status create_swapchain();
    Status create_render_pass();
    void save_capture();
    void destroy_swapchain();
    vk::Context& ctx_;
    GLFWwindow* window_ = nullptr;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkPresentModeKHR mode_ = VK_PRESENT_MODE_FIFO_KHR;
    VkFormat format_ = VK_FORMAT_B8G8R8A8_UNORM;
    VkExtent2D extent_{0, 0};
    std::vector<VkImage> images_;
    std::vector<vk::UniqueImageView> views_;
    std::vector<vk::UniqueFramebuffer> framebuffers_;
    vk::UniqueRenderPass render_pass_;
    vk::UniqueCommandPool pool_;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    vk::UniqueSemaphore acquired_, rendered_;
    vk::UniqueFence fence_;
    WindowInput input_;
    std::string capture_file_;
    bool capture_failed_ = false;
    vk::Buffer capture_buffer_;
};

} // namespace pl::lab
