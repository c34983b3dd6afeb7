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

} // namespace pl::exec
