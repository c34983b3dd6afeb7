// Dear ImGui on top of the live lab's window: context, GLFW input hookup, the Vulkan backend
// drawing into the window's render pass. What the panel shows is panel.cpp's business.
#pragma once

#include "util/error.hpp"
#include "vk/context.hpp"
#include "vk/unique.hpp"

#include <memory>

namespace pl::lab {

class Window;

class Overlay {
  public:
    static Result<std::unique_ptr<Overlay>> create(vk::Context& ctx, Window& window);
    ~Overlay();
    Overlay(const Overlay&) = delete;
    Overlay& operator=(const Overlay&) = delete;

    void begin_frame();                // ImGui::NewFrame with the backends' inputs
    void end_frame();                  // ImGui::Render
    void record(VkCommandBuffer cb);   // inside the window's render pass
    // True while the mouse/keyboard is over a widget: the lab then ignores it (no orbit while
    // dragging a slider, no pause while typing).
    bool wants_mouse() const;
    bool wants_keyboard() const;

  private:
    explicit Overlay(vk::Context& ctx) : ctx_(ctx) {}
    vk::Context& ctx_;
    vk::UniqueDescriptorPool pool_;
    bool imgui_ = false, glfw_ = false, vulkan_ = false;
};

} // namespace pl::lab
