// Names used by the graph format for Vulkan enums that more than one module maps.
#pragma once

#include <vulkan/vulkan.h>

#include <string>

namespace pl::vk {

// never | less | equal | less_equal | greater | not_equal | greater_equal | always (default)
VkCompareOp compare_op(const std::string& name);

} // namespace pl::vk
