// Impossible states inside the host (a Vulkan call failing on valid use) abort with the call and
// its result: they are bugs or a broken driver, never a consequence of user content.
#pragma once

#include <vulkan/vulkan.h>

namespace pl::vk {

const char* result_name(VkResult r);
[[noreturn]] void fail(const char* call, VkResult r, const char* file, int line);

} // namespace pl::vk

#define VK_CHECK(call)                                                                             \
    do {                                                                                           \
        VkResult pl_vk_result_ = (call);                                                           \
        if (pl_vk_result_ != VK_SUCCESS) ::pl::vk::fail(#call, pl_vk_result_, __FILE__, __LINE__); \
    } while (0)
