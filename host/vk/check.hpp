// Impossible states inside the host (a Vulkan call failing on valid use) abort with the call and
// its result: they are bugs or a broken driver, never a consequence of user content. Two results
// are not bugs: out of memory exits 3 with a message, and VK_ERROR_DEVICE_LOST (on a GPU, a
// driver reset after a runaway shader) throws DeviceLost, which the live lab recovers from by
// recreating the device and the other verbs report (exit 3).
#pragma once

#include <vulkan/vulkan.h>

#include <stdexcept>
#include <string>

namespace pl::vk {

struct DeviceLost : std::runtime_error {
    explicit DeviceLost(const std::string& what) : std::runtime_error(what) {}
};

const char* result_name(VkResult r);
[[noreturn]] void fail(const char* call, VkResult r, const char* file, int line);

} // namespace pl::vk

#define VK_CHECK(call)                                                                             \
    do {                                                                                           \
        VkResult pl_vk_result_ = (call);                                                           \
        if (pl_vk_result_ != VK_SUCCESS) ::pl::vk::fail(#call, pl_vk_result_, __FILE__, __LINE__); \
    } while (0)
