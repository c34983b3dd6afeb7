#include "vk/context.hpp"

#include "util/scan.hpp"
#include "vk/check.hpp"

#include <algorithm>
#include <atomic>
#include <cstdio>
#include <cstdlib>
#include <cstring>

#if defined(__SANITIZE_ADDRESS__)
#include <dlfcn.h>
#include <link.h>
#endif

namespace pl::vk {

namespace {

// PASSLAB_SIMULATE_DEVICE_LOST=N: the N-th fence wait of the process (any device) reports
// VK_ERROR_DEVICE_LOST, once; "N+": every N-th wait. So the live lab's recovery (and its limit)
// can be tested on a driver that never loses its device (lavapipe). Anything else: never.
bool simulated_loss_now() {
    struct Plan {
        long at = 0;
        bool repeat = false;
    };
    static const Plan plan = [] {
        Plan p;
        const char* v = std::getenv("PASSLAB_SIMULATE_DEVICE_LOST");
        if (!v) return p;
        char* end = nullptr;
        const long n = std::strtol(v, &end, 10);
        if (n <= 0 || !end || (*end != '\0' && std::strcmp(end, "+") != 0)) return p;
        p.at = n;
        p.repeat = *end == '+';
        return p;
    }();
    static std::atomic<long> waits{0};
    if (plan.at <= 0) return false;
    const long k = ++waits;
    return plan.repeat ? k % plan.at == 0 : k == plan.at;
}

#if defined(__SANITIZE_ADDRESS__)
// Under AddressSanitizer only. The loader unloads the driver and the layers at vkDestroyInstance,
// and the few allocations they never free are then reported from "<unknown module>", which no
// suppression can name, so leak checking had to be off for every test that opens a device.
// Pinned in memory (RTLD_NODELETE) their at-exit allocations stay reachable, so LeakSanitizer
// checks everything else with no suppression for the driver (tests/lsan.supp has none).
void pin_vulkan_modules() {
    dl_iterate_phdr(
        [](dl_phdr_info* info, size_t, void*) {
            const char* n = info->dlpi_name;
            if (n && (std::strstr(n, "libvulkan_") || std::strstr(n, "libVkLayer_") || std::strstr(n, "libLLVM")))
                dlopen(n, RTLD_NOW | RTLD_NOLOAD | RTLD_NODELETE);
            return 0;
        },
        nullptr);
}
#else
void pin_vulkan_modules() {}
#endif

VKAPI_ATTR VkBool32 VKAPI_CALL debug_callback(VkDebugUtilsMessageSeverityFlagBitsEXT,
                                              VkDebugUtilsMessageTypeFlagsEXT,
                                              const VkDebugUtilsMessengerCallbackDataEXT* data,
                                              void* user) {
    Context::on_validation_message(static_cast<Context*>(user), data->pMessage);
    return VK_FALSE;
}

bool layer_available(const char* name) {
    uint32_t n = 0;
    vkEnumerateInstanceLayerProperties(&n, nullptr);
    std::vector<VkLayerProperties> layers(n);
    vkEnumerateInstanceLayerProperties(&n, layers.data());
    for (const auto& l : layers)
        if (std::strcmp(l.layerName, name) == 0) return true;
    return false;
}

bool device_extension_available(VkPhysicalDevice pd, const char* name) {
    uint32_t n = 0;
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, nullptr);
    std::vector<VkExtensionProperties> exts(n);
    vkEnumerateDeviceExtensionProperties(pd, nullptr, &n, exts.data());
    for (const auto& e : exts)
        if (std::strcmp(e.extensionName, name) == 0) return true;
    return false;
}

// Real GPUs first: discrete, integrated, virtual, then CPU implementations like lavapipe.
int type_rank(VkPhysicalDeviceType t) {
    switch (t) {
    case VK_PHYSICAL_DEVICE_TYPE_DISCRETE_GPU: return 0;
    case VK_PHYSICAL_DEVICE_TYPE_INTEGRATED_GPU: return 1;
    case VK_PHYSICAL_DEVICE_TYPE_VIRTUAL_GPU: return 2;
    case VK_PHYSICAL_DEVICE_TYPE_CPU: return 3;
    default: return 4;
    }
}

Error env_error(std::string msg) {
    Error e = make_error(std::move(msg));
    e.code = ExitCode::environment;
    return e;
}

} // namespace

std::vector<std::string> DeviceFeatures::names() const {
    std::vector<std::string> out;
    auto add = [&](bool b, const char* n) {
        if (b) out.emplace_back(n);
    };
    add(geometry_shader, "geometry_shader");
    add(tessellation_shader, "tessellation_shader");
    add(fragment_stores_and_atomics, "fragment_stores_and_atomics");
    add(vertex_stores_and_atomics, "vertex_stores_and_atomics");
    add(sampler_anisotropy, "sampler_anisotropy");
    add(fill_mode_non_solid, "fill_mode_non_solid");
    add(wide_lines, "wide_lines");
    add(independent_blend, "independent_blend");
    add(depth_clamp, "depth_clamp");
    add(image_cube_array, "image_cube_array");
    add(shader_float_atomics, "shader_float_atomics");
    add(shader_int64_atomics, "shader_int64_atomics");
    add(storage_image_extended_formats, "storage_image_extended_formats");
    add(multi_draw_indirect, "multi_draw_indirect");
    add(draw_indirect_first_instance, "draw_indirect_first_instance");
    add(sample_rate_shading, "sample_rate_shading");
    add(shader_output_layer, "shader_output_layer");
    add(shader_clip_distance, "shader_clip_distance");
    add(shader_cull_distance, "shader_cull_distance");
    add(texture_compression_bc, "texture_compression_bc");
    return out;
}

bool DeviceFeatures::has(const std::string& name) const {
    auto n = names();
    return std::find(n.begin(), n.end(), name) != n.end();
}

void Context::on_validation_message(Context* self, const char* text) {
    std::lock_guard lock(self->msg_mutex_);
    std::string m = self->label_.empty() ? std::string(text) : "[" + self->label_ + "] " + text;
    std::fprintf(stderr, "validation: %s\n", m.c_str());
    self->messages_.push_back(std::move(m));
}

size_t Context::validation_message_count() const {
    std::lock_guard lock(msg_mutex_);
    return messages_.size();
}

std::vector<std::string> Context::validation_messages() const {
    std::lock_guard lock(msg_mutex_);
    return messages_;
}

void Context::set_label(std::string label) {
    std::lock_guard lock(msg_mutex_);
    label_ = std::move(label);
}

Result<std::unique_ptr<Context>> Context::create(const ContextOptions& opt) {
    std::unique_ptr<Context> ctx(new Context());

    // --- instance ---
    const char* kValidation = "VK_LAYER_KHRONOS_validation";
    std::vector<const char*> layers, extensions;
    for (const auto& e : opt.instance_extensions) extensions.push_back(e.c_str());
    if (opt.validation) {
        if (layer_available(kValidation)) {
            layers.push_back(kValidation);
            extensions.push_back(VK_EXT_DEBUG_UTILS_EXTENSION_NAME);
            ctx->validation_ = true;
        } else if (opt.require_validation) {
            return env_error("the Khronos validation layer is not installed "
                             "(Debian package vulkan-validationlayers)");
        }
    }
    VkApplicationInfo app{.sType = VK_STRUCTURE_TYPE_APPLICATION_INFO,
                          .pApplicationName = "passlab",
                          .applicationVersion = VK_MAKE_VERSION(0, 1, 0),
                          .pEngineName = "passlab",
                          .engineVersion = VK_MAKE_VERSION(0, 1, 0),
                          .apiVersion = VK_API_VERSION_1_3};
    VkDebugUtilsMessengerCreateInfoEXT messenger_info{
        .sType = VK_STRUCTURE_TYPE_DEBUG_UTILS_MESSENGER_CREATE_INFO_EXT,
        .messageSeverity = VK_DEBUG_UTILS_MESSAGE_SEVERITY_WARNING_BIT_EXT |
                           VK_DEBUG_UTILS_MESSAGE_SEVERITY_ERROR_BIT_EXT,
        .messageType = VK_DEBUG_UTILS_MESSAGE_TYPE_GENERAL_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_VALIDATION_BIT_EXT |
                       VK_DEBUG_UTILS_MESSAGE_TYPE_PERFORMANCE_BIT_EXT,
        .pfnUserCallback = debug_callback,
        .pUserData = ctx.get()};
    VkInstanceCreateInfo ici{.sType = VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO,
                             .pNext = ctx->validation_ ? &messenger_info : nullptr,
                             .pApplicationInfo = &app,
                             .enabledLayerCount = static_cast<uint32_t>(layers.size()),
                             .ppEnabledLayerNames = layers.data(),
                             .enabledExtensionCount = static_cast<uint32_t>(extensions.size()),
                             .ppEnabledExtensionNames = extensions.data()};
    VkResult r = vkCreateInstance(&ici, nullptr, &ctx->instance_);
    if (r != VK_SUCCESS)
        return env_error(std::string("cannot create a Vulkan 1.3 instance (") + result_name(r) +
                         "); install a Vulkan driver, e.g. Debian's mesa-vulkan-drivers");
    if (ctx->validation_) {
        auto create = reinterpret_cast<PFN_vkCreateDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(ctx->instance_, "vkCreateDebugUtilsMessengerEXT"));
        if (create) VK_CHECK(create(ctx->instance_, &messenger_info, nullptr, &ctx->messenger_));
    }

    // --- physical device ---
    uint32_t count = 0;
    vkEnumeratePhysicalDevices(ctx->instance_, &count, nullptr);
    std::vector<VkPhysicalDevice> devices(count);
    vkEnumeratePhysicalDevices(ctx->instance_, &count, devices.data());
    std::vector<VkPhysicalDevice> usable;
    std::vector<std::string> names;
    for (auto pd : devices) {
        VkPhysicalDeviceProperties p;
        vkGetPhysicalDeviceProperties(pd, &p);
        if (p.apiVersion < VK_API_VERSION_1_3) continue;  // dynamic rendering, sync2 are core 1.3
        usable.push_back(pd);
        names.emplace_back(p.deviceName);
    }
    if (usable.empty())
        return env_error("no Vulkan 1.3 device found; install Debian's mesa-vulkan-drivers for "
                         "the lavapipe CPU driver");
    std::string want = opt.device;
    if (want.empty())
        if (const char* env = std::getenv("PASSLAB_DEVICE")) want = env;
    size_t chosen = 0;
    if (!want.empty()) {
        bool found = false;
        bool numeric = std::all_of(want.begin(), want.end(), ::isdigit);
        // Checked: an index too large for any integer matches no device (std::stoul threw).
        auto index = scan::parse_decimal(want, usable.size());
        for (size_t i = 0; i < usable.size(); ++i) {
            if ((numeric && index && *index == i) ||
                (!numeric && names[i].find(want) != std::string::npos)) {
                chosen = i;
                found = true;
                break;
            }
        }
        if (!found) {
            Error e = env_error("no Vulkan device matches '" + want + "'");
            for (size_t i = 0; i < names.size(); ++i)
                e.notes.push_back("device " + std::to_string(i) + ": " + names[i]);
            return e;
        }
    } else {
        std::vector<size_t> idx(usable.size());
        for (size_t i = 0; i < idx.size(); ++i) idx[i] = i;
        std::stable_sort(idx.begin(), idx.end(), [&](size_t a, size_t b) {
            VkPhysicalDeviceProperties pa, pb;
            vkGetPhysicalDeviceProperties(usable[a], &pa);
            vkGetPhysicalDeviceProperties(usable[b], &pb);
            return type_rank(pa.deviceType) < type_rank(pb.deviceType);
        });
        chosen = idx[0];
    }
    ctx->physical_ = usable[chosen];
    vkGetPhysicalDeviceProperties(ctx->physical_, &ctx->props_);
    vkGetPhysicalDeviceMemoryProperties(ctx->physical_, &ctx->mem_props_);

    VkPhysicalDeviceDriverProperties driver{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_DRIVER_PROPERTIES};
    VkPhysicalDeviceProperties2 props2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_PROPERTIES_2,
                                       .pNext = &driver};
    vkGetPhysicalDeviceProperties2(ctx->physical_, &props2);
    ctx->driver_name_ = driver.driverName;
    ctx->driver_info_ = driver.driverInfo;

    // --- queue family: one queue that does graphics + compute (+ transfer implicitly) ---
    uint32_t qf_count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx->physical_, &qf_count, nullptr);
    std::vector<VkQueueFamilyProperties> qfs(qf_count);
    vkGetPhysicalDeviceQueueFamilyProperties(ctx->physical_, &qf_count, qfs.data());
    bool have_queue = false;
    for (uint32_t i = 0; i < qf_count; ++i) {
        if ((qfs[i].queueFlags & VK_QUEUE_GRAPHICS_BIT) && (qfs[i].queueFlags & VK_QUEUE_COMPUTE_BIT)) {
            ctx->queue_family_ = i;
            have_queue = true;
            break;
        }
    }
    if (!have_queue) return env_error("the Vulkan device has no graphics+compute queue");

    // --- features: enable what presets may use, if the device has it ---
    VkPhysicalDeviceShaderAtomicFloatFeaturesEXT atomic_float{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
    VkPhysicalDeviceVulkan13Features f13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    VkPhysicalDeviceVulkan12Features f12{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                         .pNext = &f13};
    VkPhysicalDeviceVulkan11Features f11{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES,
                                         .pNext = &f12};
    VkPhysicalDeviceFeatures2 f2{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_FEATURES_2, .pNext = &f11};
    bool has_atomic_float = device_extension_available(ctx->physical_, VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);
    if (has_atomic_float) f13.pNext = &atomic_float;
    vkGetPhysicalDeviceFeatures2(ctx->physical_, &f2);

    if (!f13.dynamicRendering || !f13.synchronization2)
        return env_error("the Vulkan device lacks dynamicRendering or synchronization2");

    // Keep only what we use; everything else off so behaviour matches across drivers.
    VkPhysicalDeviceFeatures have = f2.features;
    VkPhysicalDeviceFeatures use{};
    use.geometryShader = have.geometryShader;
    use.tessellationShader = have.tessellationShader;
    use.fragmentStoresAndAtomics = have.fragmentStoresAndAtomics;
    use.vertexPipelineStoresAndAtomics = have.vertexPipelineStoresAndAtomics;
    use.samplerAnisotropy = have.samplerAnisotropy;
    use.fillModeNonSolid = have.fillModeNonSolid;
    use.wideLines = have.wideLines;
    use.independentBlend = have.independentBlend;
    use.depthClamp = have.depthClamp;
    use.depthBiasClamp = have.depthBiasClamp;
    use.imageCubeArray = have.imageCubeArray;
    use.shaderStorageImageExtendedFormats = have.shaderStorageImageExtendedFormats;
    use.shaderStorageImageWriteWithoutFormat = have.shaderStorageImageWriteWithoutFormat;
    use.multiDrawIndirect = have.multiDrawIndirect;
    use.drawIndirectFirstInstance = have.drawIndirectFirstInstance;
    use.sampleRateShading = have.sampleRateShading;
    use.shaderInt64 = have.shaderInt64;
    use.shaderImageGatherExtended = have.shaderImageGatherExtended;
    use.largePoints = have.largePoints;
    use.shaderClipDistance = have.shaderClipDistance;
    use.shaderCullDistance = have.shaderCullDistance;
    use.textureCompressionBC = have.textureCompressionBC;
    f2.features = use;
    VkPhysicalDeviceVulkan13Features e13{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    e13.dynamicRendering = VK_TRUE;
    e13.synchronization2 = VK_TRUE;
    // glslang 12 emits LocalSizeId for compute shaders, which needs maintenance4.
    e13.maintenance4 = f13.maintenance4;
    VkPhysicalDeviceVulkan12Features e12{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_2_FEATURES,
                                         .pNext = &e13};
    e12.shaderBufferInt64Atomics = f12.shaderBufferInt64Atomics;
    e12.shaderOutputLayer = f12.shaderOutputLayer;
    e12.shaderOutputViewportIndex = f12.shaderOutputViewportIndex;
    e12.scalarBlockLayout = f12.scalarBlockLayout;
    e12.timelineSemaphore = f12.timelineSemaphore;
    e12.hostQueryReset = f12.hostQueryReset;
    VkPhysicalDeviceVulkan11Features e11{.sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_1_FEATURES,
                                         .pNext = &e12};
    e11.shaderDrawParameters = f11.shaderDrawParameters;
    VkPhysicalDeviceShaderAtomicFloatFeaturesEXT eaf{
        .sType = VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_SHADER_ATOMIC_FLOAT_FEATURES_EXT};
    std::vector<const char*> dev_ext;
    if (has_atomic_float) {
        eaf.shaderBufferFloat32Atomics = atomic_float.shaderBufferFloat32Atomics;
        eaf.shaderBufferFloat32AtomicAdd = atomic_float.shaderBufferFloat32AtomicAdd;
        eaf.shaderSharedFloat32Atomics = atomic_float.shaderSharedFloat32Atomics;
        eaf.shaderSharedFloat32AtomicAdd = atomic_float.shaderSharedFloat32AtomicAdd;
        eaf.shaderImageFloat32Atomics = atomic_float.shaderImageFloat32Atomics;
        eaf.shaderImageFloat32AtomicAdd = atomic_float.shaderImageFloat32AtomicAdd;
        e13.pNext = &eaf;
        dev_ext.push_back(VK_EXT_SHADER_ATOMIC_FLOAT_EXTENSION_NAME);
    }
    if (opt.swapchain) dev_ext.push_back(VK_KHR_SWAPCHAIN_EXTENSION_NAME);
    f2.pNext = &e11;

    auto& F = ctx->features_;
    F.geometry_shader = use.geometryShader;
    F.tessellation_shader = use.tessellationShader;
    F.fragment_stores_and_atomics = use.fragmentStoresAndAtomics;
    F.vertex_stores_and_atomics = use.vertexPipelineStoresAndAtomics;
    F.sampler_anisotropy = use.samplerAnisotropy;
    F.fill_mode_non_solid = use.fillModeNonSolid;
    F.wide_lines = use.wideLines;
    F.independent_blend = use.independentBlend;
    F.depth_clamp = use.depthClamp;
    F.image_cube_array = use.imageCubeArray;
    F.shader_float_atomics = has_atomic_float && atomic_float.shaderBufferFloat32AtomicAdd;
    F.shader_int64_atomics = f12.shaderBufferInt64Atomics && have.shaderInt64;
    F.storage_image_extended_formats = use.shaderStorageImageExtendedFormats;
    F.multi_draw_indirect = use.multiDrawIndirect;
    F.draw_indirect_first_instance = use.drawIndirectFirstInstance;
    F.sample_rate_shading = use.sampleRateShading;
    F.shader_output_layer = f12.shaderOutputLayer;
    F.shader_clip_distance = use.shaderClipDistance;
    F.shader_cull_distance = use.shaderCullDistance;
    F.texture_compression_bc = use.textureCompressionBC;
    F.max_anisotropy = use.samplerAnisotropy ? ctx->props_.limits.maxSamplerAnisotropy : 1.0f;

    float priority = 1.0f;
    VkDeviceQueueCreateInfo qci{.sType = VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO,
                                .queueFamilyIndex = ctx->queue_family_,
                                .queueCount = 1,
                                .pQueuePriorities = &priority};
    VkDeviceCreateInfo dci{.sType = VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO,
                           .pNext = &f2,
                           .queueCreateInfoCount = 1,
                           .pQueueCreateInfos = &qci,
                           .enabledExtensionCount = static_cast<uint32_t>(dev_ext.size()),
                           .ppEnabledExtensionNames = dev_ext.data()};
    r = vkCreateDevice(ctx->physical_, &dci, nullptr, &ctx->device_);
    if (r != VK_SUCCESS)
        return env_error(std::string("cannot create the Vulkan device: ") + result_name(r));
    vkGetDeviceQueue(ctx->device_, ctx->queue_family_, 0, &ctx->queue_);
    pin_vulkan_modules();

    VkCommandPoolCreateInfo pci{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                .queueFamilyIndex = ctx->queue_family_};
    VkCommandPool pool;
    VK_CHECK(vkCreateCommandPool(ctx->device_, &pci, nullptr, &pool));
    ctx->pool_ = UniqueCommandPool(ctx->device_, pool);

    if (opt.verbose) std::fprintf(stderr, "device: %s\n", ctx->device_description().c_str());
    return ctx;
}

Context::~Context() {
    if (hung_) return;  // a runaway shader may still execute: leak rather than hang or crash
    if (device_) {
        vkDeviceWaitIdle(device_);
        collect(UINT64_MAX);
        pool_.reset();
        vkDestroyDevice(device_, nullptr);
    }
    if (messenger_) {
        auto destroy = reinterpret_cast<PFN_vkDestroyDebugUtilsMessengerEXT>(
            vkGetInstanceProcAddr(instance_, "vkDestroyDebugUtilsMessengerEXT"));
        if (destroy) destroy(instance_, messenger_, nullptr);
    }
    if (instance_) vkDestroyInstance(instance_, nullptr);
}

std::string Context::device_description() const {
    uint32_t v = props_.apiVersion;
    return std::string(props_.deviceName) + " | driver " + driver_name_ + " " + driver_info_ +
           " | Vulkan " + std::to_string(VK_API_VERSION_MAJOR(v)) + "." +
           std::to_string(VK_API_VERSION_MINOR(v)) + "." + std::to_string(VK_API_VERSION_PATCH(v));
}

uint32_t Context::memory_type(uint32_t type_bits, VkMemoryPropertyFlags wanted) const {
    for (uint32_t i = 0; i < mem_props_.memoryTypeCount; ++i)
        if ((type_bits & (1u << i)) && (mem_props_.memoryTypes[i].propertyFlags & wanted) == wanted)
            return i;
    // Host-visible memory is always available for buffers; for device-local fall back to any.
    for (uint32_t i = 0; i < mem_props_.memoryTypeCount; ++i)
        if (type_bits & (1u << i)) return i;
    fail("memory_type", VK_ERROR_OUT_OF_DEVICE_MEMORY, __FILE__, __LINE__);
}

VkDeviceSize Context::largest_device_heap() const {
    VkDeviceSize best = 0;
    for (uint32_t i = 0; i < mem_props_.memoryHeapCount; ++i)
        if (mem_props_.memoryHeaps[i].flags & VK_MEMORY_HEAP_DEVICE_LOCAL_BIT) best = std::max(best, mem_props_.memoryHeaps[i].size);
    return best;
}

Status Context::wait(VkFence fence, std::chrono::milliseconds timeout, const std::string& what, const std::string& cause) {
    uint64_t ns = static_cast<uint64_t>(timeout.count()) * 1000000ull;
    VkResult r = vkWaitForFences(device_, 1, &fence, VK_TRUE, ns);
    if (r == VK_SUCCESS && simulated_loss_now()) r = VK_ERROR_DEVICE_LOST;  // the work did finish: safe to destroy
    if (r == VK_TIMEOUT) {
        hung_ = true;
        Error e = make_error(what + " did not finish within " +
                             std::to_string(timeout.count() / 1000.0).substr(0, 5) +
                             " s: " + cause);
        e.hint = "raise the limit with --timeout SECONDS if the work is really that long";
        return e;
    }
    if (r == VK_ERROR_DEVICE_LOST) {
        lost_ = true;
        Error e = make_error(what + " lost the Vulkan device (VK_ERROR_DEVICE_LOST)");
        e.code = ExitCode::environment;
        return e;
    }
    VK_CHECK(r);
    return ok_status();
}

Status Context::run_once(const std::function<void(VkCommandBuffer)>& record,
                         std::chrono::milliseconds timeout) {
    VkCommandBufferAllocateInfo ai{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                   .commandPool = pool_,
                                   .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                   .commandBufferCount = 1};
    VkCommandBuffer cb;
    VK_CHECK(vkAllocateCommandBuffers(device_, &ai, &cb));
    VkCommandBufferBeginInfo bi{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(cb, &bi));
    record(cb);
    VK_CHECK(vkEndCommandBuffer(cb));
    VkFenceCreateInfo fci{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence_raw;
    VK_CHECK(vkCreateFence(device_, &fci, nullptr, &fence_raw));
    UniqueFence fence(device_, fence_raw);
    VkSubmitInfo si{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cb};
    uint64_t serial = begin_submit();
    VK_CHECK(vkQueueSubmit(queue_, 1, &si, fence));
    Status s = wait(fence, timeout, "GPU work");
    if (!s) {
        // The command buffer may still be executing: leak it and the fence rather than free
        // objects in use; the process is about to report the error anyway.
        (void)fence.release();
        return s;
    }
    vkFreeCommandBuffers(device_, pool_, 1, &cb);
    collect(serial);
    return s;
}

void Context::collect(uint64_t completed_serial) {
    std::erase_if(retired_, [&](const Retired& r) { return r.serial <= completed_serial; });
}

} // namespace pl::vk
