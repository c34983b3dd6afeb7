#include "overlay.hpp"

#include "vk/check.hpp"
#include "window.hpp"

#include <imgui.h>
#include <backends/imgui_impl_glfw.h>
#include <backends/imgui_impl_vulkan.h>

namespace pl::lab {

Result<std::unique_ptr<Overlay>> Overlay::create(vk::Context& ctx, Window& window) {
    std::unique_ptr<Overlay> o(new Overlay(ctx));
    VkDevice dev = ctx.device();
    // The backend needs one set, for its font atlas.
    VkDescriptorPoolSize size{VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER, 1};
    VkDescriptorPoolCreateInfo dci{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                   .flags = VK_DESCRIPTOR_POOL_CREATE_FREE_DESCRIPTOR_SET_BIT,
                                   .maxSets = 1,
                                   .poolSizeCount = 1,
                                   .pPoolSizes = &size};
    VkDescriptorPool pool;
    VK_CHECK(vkCreateDescriptorPool(dev, &dci, nullptr, &pool));
    o->pool_ = vk::UniqueDescriptorPool(dev, pool);

    IMGUI_CHECKVERSION();
    ImGui::CreateContext();
    o->imgui_ = true;
    ImGuiIO& io = ImGui::GetIO();
    io.IniFilename = nullptr;  // never write imgui.ini into the user's working folder
    ImGui::StyleColorsDark();
    ImGui::GetStyle().Alpha = 0.94f;
    // HiDPI: the panel keeps its physical size on a 2x display.
    if (float scale = window.content_scale(); scale > 1.01f) {
        ImGui::GetStyle().ScaleAllSizes(scale);
        io.FontGlobalScale = scale;
    }
    // install_callbacks = true chains the window's own GLFW callbacks (orbit, keys).
    if (!ImGui_ImplGlfw_InitForVulkan(window.handle(), true)) return make_error("cannot initialise the ImGui GLFW backend");
    o->glfw_ = true;
    ImGui_ImplVulkan_InitInfo ii{};
    ii.Instance = ctx.instance();
    ii.PhysicalDevice = ctx.physical();
    ii.Device = dev;
    ii.QueueFamily = ctx.queue_family();
    ii.Queue = ctx.queue();
    ii.DescriptorPool = pool;
    ii.MinImageCount = 2;
    ii.ImageCount = std::max(2u, window.image_count());
    ii.MSAASamples = VK_SAMPLE_COUNT_1_BIT;
    if (!ImGui_ImplVulkan_Init(&ii, window.render_pass())) return make_error("cannot initialise the ImGui Vulkan backend");
    o->vulkan_ = true;

    // Font atlas upload, once.
    if (auto st = ctx.run_once([](VkCommandBuffer cb) { ImGui_ImplVulkan_CreateFontsTexture(cb); }, std::chrono::seconds(20)); !st)
        return st.error();
    ImGui_ImplVulkan_DestroyFontUploadObjects();
    return o;
}

Overlay::~Overlay() {
    if (ctx_.device() && !ctx_.hung()) vkDeviceWaitIdle(ctx_.device());
    if (vulkan_) ImGui_ImplVulkan_Shutdown();
    if (glfw_) ImGui_ImplGlfw_Shutdown();
    if (imgui_) ImGui::DestroyContext();
}

void Overlay::begin_frame() {
    ImGui_ImplVulkan_NewFrame();
    ImGui_ImplGlfw_NewFrame();
    ImGui::NewFrame();
}

void Overlay::end_frame() { ImGui::Render(); }

void Overlay::record(VkCommandBuffer cb) {
    if (ImDrawData* d = ImGui::GetDrawData()) ImGui_ImplVulkan_RenderDrawData(d, cb);
}

bool Overlay::wants_mouse() const { return ImGui::GetIO().WantCaptureMouse; }
bool Overlay::wants_keyboard() const { return ImGui::GetIO().WantCaptureKeyboard; }

} // namespace pl::lab
