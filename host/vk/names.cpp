#include "vk/names.hpp"

namespace pl::vk {

VkCompareOp compare_op(const std::string& s) {
    if (s == "never") return VK_COMPARE_OP_NEVER;
    if (s == "less") return VK_COMPARE_OP_LESS;
    if (s == "equal") return VK_COMPARE_OP_EQUAL;
    if (s == "less_equal") return VK_COMPARE_OP_LESS_OR_EQUAL;
    if (s == "greater") return VK_COMPARE_OP_GREATER;
    if (s == "not_equal") return VK_COMPARE_OP_NOT_EQUAL;
    if (s == "greater_equal") return VK_COMPARE_OP_GREATER_OR_EQUAL;
    return VK_COMPARE_OP_ALWAYS;
}

} // namespace pl::vk
