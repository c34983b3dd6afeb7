// Device limits that a valid graph can still exceed on a given device, checked after sizes are
// evaluated and before anything is recorded, so the user sees the buffer's `size` key, the limit
// and the device instead of a raw validation message or undefined behaviour.
#pragma once

#include "exec/build.hpp"

#include <vulkan/vulkan.h>

#include <map>
#include <string>

namespace pl::exec {

// Every buffer binding against maxStorageBufferRange / maxUniformBufferRange (the whole buffer
// is bound, so its size is the range). `sizes`: each graph buffer's evaluated size in bytes;
// `device` names the device in the message. Pure, so a unit test can give it any limits.
Status check_binding_limits(const VkPhysicalDeviceLimits& limits, const std::string& device, const CompiledGraph& g,
                            const std::map<std::string, VkDeviceSize>& sizes);

// An image as it is about to be created against maxImageDimension1D/2D/3D/Cube and
// maxImageArrayLayers; the error points at the image's `size` (or `layers`) key.
Status check_image_limits(const VkPhysicalDeviceLimits& limits, const std::string& device, const graph::ImageDesc& d,
                          VkExtent3D extent, uint32_t layers, bool is_3d, bool is_cube);

// Every compute pass's workgroup against maxComputeWorkGroupSize, maxComputeWorkGroupInvocations
// and maxComputeSharedMemorySize (the error points at the `shared` declaration or the shader).
Status check_compute_limits(const VkPhysicalDeviceLimits& limits, const std::string& device, const CompiledGraph& g);

// A running total of the memory the graph's resources need, against the largest device heap:
// refused with the resource that tips it over, before the allocation that would fail.
struct MemoryBudget {
    VkDeviceSize heap = 0, used = 0;
    std::string device;
    Status add(VkDeviceSize bytes, const std::string& what, const SourceLoc& loc, const std::string& resource);
};

} // namespace pl::exec
