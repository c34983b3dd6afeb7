#include "vk/check.hpp"

#include <cstdio>
#include <cstdlib>

namespace pl::vk {

const char* result_name(VkResult r) {
    switch (r) {
#define PL_CASE(x) case x: return #x;
        PL_CASE(VK_SUCCESS) PL_CASE(VK_NOT_READY) PL_CASE(VK_TIMEOUT) PL_CASE(VK_INCOMPLETE)
        PL_CASE(VK_ERROR_OUT_OF_HOST_MEMORY) PL_CASE(VK_ERROR_OUT_OF_DEVICE_MEMORY)
        PL_CASE(VK_ERROR_INITIALIZATION_FAILED) PL_CASE(VK_ERROR_DEVICE_LOST)
        PL_CASE(VK_ERROR_MEMORY_MAP_FAILED) PL_CASE(VK_ERROR_LAYER_NOT_PRESENT)
        PL_CASE(VK_ERROR_EXTENSION_NOT_PRESENT) PL_CASE(VK_ERROR_FEATURE_NOT_PRESENT)
        PL_CASE(VK_ERROR_INCOMPATIBLE_DRIVER) PL_CASE(VK_ERROR_TOO_MANY_OBJECTS)
        PL_CASE(VK_ERROR_FORMAT_NOT_SUPPORTED) PL_CASE(VK_ERROR_OUT_OF_DATE_KHR)
        PL_CASE(VK_SUBOPTIMAL_KHR) PL_CASE(VK_ERROR_SURFACE_LOST_KHR)
#undef PL_CASE
    default: return "VK_RESULT_UNKNOWN";
    }
}

void fail(const char* call, VkResult r, const char* file, int line) {
    if (r == VK_ERROR_OUT_OF_DEVICE_MEMORY || r == VK_ERROR_OUT_OF_HOST_MEMORY) {
        // Not a bug: the machine ran out (resource sizes are checked against the heap before
        // allocating, but a process memory limit or other programs can still make it fail).
        std::fprintf(stderr, "passlab: error: out of memory: %s returned %s\n    hint: make the images or buffers smaller (--size, size expressions)\n",
                     call, result_name(r));
        std::fflush(stderr);
        std::_Exit(3);  // the exit code of environment errors (docs/cli.md)
    }
    if (r == VK_ERROR_DEVICE_LOST) throw DeviceLost(std::string(call) + " returned VK_ERROR_DEVICE_LOST");
    std::fprintf(stderr, "passlab: internal Vulkan failure: %s returned %s (%d) at %s:%d\n", call,
                 result_name(r), static_cast<int>(r), file, line);
    std::abort();
}

} // namespace pl::vk
