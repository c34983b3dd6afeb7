// The live lab's window: a GLFW window with a Vulkan surface and swapchain. Only `passlab run`
// creates one; headless verbs never initialise GLFW.
#pragma once

#include "util/error.hpp"
#include "vk/context.hpp"

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
    bool pause_toggled = false, step = false, screenshot = false;
};

class Window {
  public:
    static Result<std::unique_ptr<Window>> create(vk::Context& ctx, int width, int height, const std::string& title,
                                                  VkPresentModeKHR mode);
    ~Window();

    bool should_close() const;
    void poll();
    // Acquires a swapchain image, lets `record` fill it (it arrives in TRANSFER_DST layout),
    // and presents. Recreates the swapchain when the window size changed.
    Status present(const std::function<Status(VkCommandBuffer, VkImage, VkExtent2D)>& record);
    void set_title(const std::string& t);
    // The input since the last call (motion, wheel and key presses are consumed).
    WindowInput take_input();
    WindowInput& input() { return input_; }

  private:
    Window(vk::Context& ctx) : ctx_(ctx) {}
    Status create_swapchain();
    void destroy_swapchain();
    vk::Context& ctx_;
    GLFWwindow* window_ = nullptr;
    VkSurfaceKHR surface_ = VK_NULL_HANDLE;
    VkSwapchainKHR swapchain_ = VK_NULL_HANDLE;
    VkPresentModeKHR mode_ = VK_PRESENT_MODE_FIFO_KHR;
    VkFormat format_ = VK_FORMAT_B8G8R8A8_UNORM;
    VkExtent2D extent_{0, 0};
    std::vector<VkImage> images_;
    vk::UniqueCommandPool pool_;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    vk::UniqueSemaphore acquired_, rendered_;
    vk::UniqueFence fence_;
    WindowInput input_;
};

} // namespace pl::lab
