// The Vulkan instance, the chosen physical device, the logical device and its one queue.
// Device choice is explicit and printed: a real GPU if present, else lavapipe; PASSLAB_DEVICE
// (index or name substring) or ContextOptions::device overrides it.
#pragma once

#include "util/error.hpp"
#include "vk/unique.hpp"

#include <vulkan/vulkan.h>

#include <chrono>
#include <functional>
#include <memory>
#include <mutex>
#include <string>
#include <vector>

namespace pl::vk {

struct ContextOptions {
    bool validation = false;        // Khronos validation layer (if installed)
    bool require_validation = false;  // fail if the layer is missing (tests)
    std::string device;             // index or name substring; "" = PASSLAB_DEVICE or automatic
    std::vector<std::string> instance_extensions;  // e.g. from glfwGetRequiredInstanceExtensions
    bool swapchain = false;         // enable VK_KHR_swapchain on the device
    bool verbose = true;            // print the chosen device to stderr
};

// Optional capabilities presets may ask for (`requires = [...]` in tests).
struct DeviceFeatures {
    bool geometry_shader = false, tessellation_shader = false;
    bool fragment_stores_and_atomics = false, vertex_stores_and_atomics = false;
    bool sampler_anisotropy = false, fill_mode_non_solid = false, wide_lines = false;
    bool independent_blend = false, depth_clamp = false, image_cube_array = false;
    bool shader_float_atomics = false;      // VK_EXT_shader_atomic_float buffer/image float add
    bool shader_int64_atomics = false;      // 64-bit buffer atomics
    bool storage_image_extended_formats = false;
    bool multi_draw_indirect = false, draw_indirect_first_instance = false;
    bool sample_rate_shading = false;
    bool shader_output_layer = false;       // gl_Layer from vertex stage (Vulkan 1.2)
    bool shader_clip_distance = false;      // gl_ClipDistance (user clip planes: mirrors, portals)
    bool shader_cull_distance = false;      // gl_CullDistance
    bool texture_compression_bc = false;    // BC1..BC7 sampled images (desktop GPUs, lavapipe)
    float max_anisotropy = 1.0f;
    std::vector<std::string> names() const;  // the true ones, as used in `requires`
    bool has(const std::string& name) const;
};

class Context {
  public:
    static Result<std::unique_ptr<Context>> create(const ContextOptions& opt);
    ~Context();
    Context(const Context&) = delete;
    Context& operator=(const Context&) = delete;

    VkInstance instance() const { return instance_; }
    VkPhysicalDevice physical() const { return physical_; }
    VkDevice device() const { return device_; }
    VkQueue queue() const { return queue_; }
    uint32_t queue_family() const { return queue_family_; }
    const VkPhysicalDeviceProperties& properties() const { return props_; }
    const DeviceFeatures& features() const { return features_; }
    // "llvmpipe (LLVM 15.0.6, 256 bits) | llvmpipe Mesa 22.3.6 (LLVM 15.0.6) | Vulkan 1.3.230"
    std::string device_description() const;
    std::string driver_name() const { return driver_name_; }
    std::string driver_info() const { return driver_info_; }
    bool validation_enabled() const { return validation_; }
    // True after a watchdog timeout: the GPU may still be running the shader, so nothing may be
    // waited for or destroyed; callers end the process (std::_Exit) after reporting.
    bool hung() const { return hung_; }
    // True once a wait reported VK_ERROR_DEVICE_LOST (or PASSLAB_SIMULATE_DEVICE_LOST=N made the
    // N-th fence wait of the process report it, "N+" every N-th, for tests): nothing more runs on this device;
    // its objects may still be destroyed (Vulkan allows that on a lost device).
    bool lost() const { return lost_; }

    uint32_t memory_type(uint32_t type_bits, VkMemoryPropertyFlags wanted) const;
    // Bytes of the largest device-local memory heap (all of system memory on a CPU driver).
    VkDeviceSize largest_device_heap() const;

    // Validation messages seen so far (warnings and errors); each is prefixed with the label
    // current when it arrived (the pass being recorded).
    size_t validation_message_count() const;
    std::vector<std::string> validation_messages() const;
    void set_label(std::string label);

    // Records with `record` into a fresh command buffer, submits, and waits at most `timeout`.
    // A timeout is a user error (a runaway shader), reported as such.
    Status run_once(const std::function<void(VkCommandBuffer)>& record,
                    std::chrono::milliseconds timeout = std::chrono::seconds(30));
    // Waits for `fence` with a watchdog; the error names `what` and the likely `cause`.
    Status wait(VkFence fence, std::chrono::milliseconds timeout, const std::string& what,
                const std::string& cause = "a shader probably runs away (endless or very long loop)");

    // Deferred destruction: `object` stays alive until the GPU work submitted so far is done
    // (collect() is called after each fence wait). A reload never frees what a frame still uses.
    template <class T> void retire(T&& object) {
        auto holder = std::make_shared<std::decay_t<T>>(std::forward<T>(object));
        retired_.push_back({submit_serial_, [holder] {}});
    }
    uint64_t begin_submit() { return ++submit_serial_; }
    void collect(uint64_t completed_serial);

    static void on_validation_message(Context* self, const char* text);

  private:
    Context() = default;
    VkInstance instance_ = VK_NULL_HANDLE;
    VkDebugUtilsMessengerEXT messenger_ = VK_NULL_HANDLE;
    VkPhysicalDevice physical_ = VK_NULL_HANDLE;
    VkDevice device_ = VK_NULL_HANDLE;
    VkQueue queue_ = VK_NULL_HANDLE;
    uint32_t queue_family_ = 0;
    VkPhysicalDeviceProperties props_{};
    VkPhysicalDeviceMemoryProperties mem_props_{};
    DeviceFeatures features_;
    std::string driver_name_, driver_info_;
    bool validation_ = false;
    bool hung_ = false;
    bool lost_ = false;
    UniqueCommandPool pool_;

    mutable std::mutex msg_mutex_;
    std::vector<std::string> messages_;
    std::string label_;

    struct Retired {
        uint64_t serial;
        std::function<void()> release;
    };
    std::vector<Retired> retired_;
    uint64_t submit_serial_ = 0;
};

} // namespace pl::vk
