// Conversion between RGBA float and the bytes of a texel of a given format, for uploads of
// image files/generators and for readback. Depth formats read as depth in .r.
#pragma once

#include "vk/formats.hpp"

#include <cstdint>

namespace pl::exec {

// Returns false if the format cannot be converted (block-compressed, etc.).
bool encode_texel(const vk::FormatInfo& f, const float rgba[4], uint8_t* out);
// `depth_copy`: the bytes come from a depth-aspect copy (D24 in 32-bit words, D32S8 as float).
bool decode_texel(const vk::FormatInfo& f, const uint8_t* in, float rgba[4], bool depth_copy);
// Bytes per texel as laid out by a buffer copy of the colour or depth aspect.
uint32_t copy_texel_size(const vk::FormatInfo& f);

float half_to_float(uint16_t h);
uint16_t float_to_half(float f);

} // namespace pl::exec
