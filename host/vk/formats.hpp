// The image format names the graph format accepts, and what each maps to in Vulkan.
#pragma once

#include <vulkan/vulkan.h>

#include <string>
#include <vector>

namespace pl::vk {

struct FormatInfo {
    const char* name;       // as written in preset.toml
    VkFormat format;
    int components;         // 1..4
    int bytes_per_texel;    // for block-compressed formats: bytes per block
    bool is_depth, has_stencil;
    bool is_float;          // float or unorm/snorm (sampled as float)
    bool is_integer;        // uint/sint (isampler/usampler, integer atomics)
    bool is_srgb;
    const char* glsl_storage;  // GLSL image format qualifier ("" if not usable as storage)
    int block = 1;          // block side in texels: 1, or 4 for BC1 (4x4 texels in 8 bytes)
    bool compressed() const { return block > 1; }
};

// nullptr if unknown.
const FormatInfo* find_format(const std::string& name);
const FormatInfo* find_format(VkFormat f);
std::vector<std::string> format_names();

} // namespace pl::vk
