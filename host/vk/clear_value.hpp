// Clear colours as the device reads them. preset.toml writes clear values as plain numbers, but
// VkClearColorValue is a union: the member the device reads is chosen by the image's format
// (float32 for float/unorm/snorm, uint32 for UINT, int32 for SINT). Writing float bits for an
// integer format clears an r32ui image to 1084227584 instead of 5, and linked-list heads that
// must start at 0xffffffff depend on an exact integer clear.
#pragma once

#include "vk/formats.hpp"

#include <array>
#include <string>

namespace pl::vk {

// Why `v` cannot clear an image of format `f` exactly ("" when it can): for integer formats
// every component must be an integer within the channel's range (r32ui 0..4294967295, r32i
// -2147483648..2147483647, rgba16ui 0..65535); float formats take any finite value.
std::string clear_value_problem(const FormatInfo& f, const std::array<double, 4>& v);

// The union member `f` is read through, filled from `v` (valid values: see above).
VkClearColorValue clear_color(const FormatInfo& f, const std::array<double, 4>& v);

// A buffer fill (vkCmdFillBuffer) repeats one 32-bit word: "" when `v` is an integer in
// 0..4294967295, else why not.
std::string fill_value_problem(double v);

} // namespace pl::vk
