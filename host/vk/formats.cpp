#include "vk/formats.hpp"

namespace pl::vk {

namespace {
// clang-format off
const FormatInfo kFormats[] = {
    // name          format                              c  B  depth  stencil float  int    srgb   storage
    {"r8",           VK_FORMAT_R8_UNORM,                 1, 1, false, false, true,  false, false, "r8"},
    {"rg8",          VK_FORMAT_R8G8_UNORM,               2, 2, false, false, true,  false, false, "rg8"},
    {"rgba8",        VK_FORMAT_R8G8B8A8_UNORM,           4, 4, false, false, true,  false, false, "rgba8"},
    {"rgba8_srgb",   VK_FORMAT_R8G8B8A8_SRGB,            4, 4, false, false, true,  false, true,  ""},
    {"bgra8",        VK_FORMAT_B8G8R8A8_UNORM,           4, 4, false, false, true,  false, false, ""},
    {"bgra8_srgb",   VK_FORMAT_B8G8R8A8_SRGB,            4, 4, false, false, true,  false, true,  ""},
    {"rgba8_snorm",  VK_FORMAT_R8G8B8A8_SNORM,           4, 4, false, false, true,  false, false, "rgba8_snorm"},
    {"rgb10a2",      VK_FORMAT_A2B10G10R10_UNORM_PACK32, 4, 4, false, false, true,  false, false, "rgb10_a2"},
    {"r11g11b10f",   VK_FORMAT_B10G11R11_UFLOAT_PACK32,  3, 4, false, false, true,  false, false, "r11f_g11f_b10f"},
    {"r16f",         VK_FORMAT_R16_SFLOAT,               1, 2, false, false, true,  false, false, "r16f"},
    {"rg16f",        VK_FORMAT_R16G16_SFLOAT,            2, 4, false, false, true,  false, false, "rg16f"},
    {"rgba16f",      VK_FORMAT_R16G16B16A16_SFLOAT,      4, 8, false, false, true,  false, false, "rgba16f"},
    {"r32f",         VK_FORMAT_R32_SFLOAT,               1, 4, false, false, true,  false, false, "r32f"},
    {"rg32f",        VK_FORMAT_R32G32_SFLOAT,            2, 8, false, false, true,  false, false, "rg32f"},
    {"rgba32f",      VK_FORMAT_R32G32B32A32_SFLOAT,      4, 16, false, false, true, false, false, "rgba32f"},
    {"r32ui",        VK_FORMAT_R32_UINT,                 1, 4, false, false, false, true,  false, "r32ui"},
    {"rg32ui",       VK_FORMAT_R32G32_UINT,              2, 8, false, false, false, true,  false, "rg32ui"},
    {"rgba32ui",     VK_FORMAT_R32G32B32A32_UINT,        4, 16, false, false, false, true, false, "rgba32ui"},
    {"r32i",         VK_FORMAT_R32_SINT,                 1, 4, false, false, false, true,  false, "r32i"},
    {"rgba32i",      VK_FORMAT_R32G32B32A32_SINT,        4, 16, false, false, false, true, false, "rgba32i"},
    {"rgba16ui",     VK_FORMAT_R16G16B16A16_UINT,        4, 8, false, false, false, true,  false, "rgba16ui"},
    {"d16",          VK_FORMAT_D16_UNORM,                1, 2, true,  false, true,  false, false, ""},
    {"d32",          VK_FORMAT_D32_SFLOAT,               1, 4, true,  false, true,  false, false, ""},
    {"d24s8",        VK_FORMAT_D24_UNORM_S8_UINT,        2, 4, true,  true,  true,  false, false, ""},
    {"d32s8",        VK_FORMAT_D32_SFLOAT_S8_UINT,       2, 8, true,  true,  true,  false, false, ""},
    // Block-compressed (S3TC/DXT1): sampled only, filled by a `copy` pass from a buffer of blocks.
    {"bc1_rgba",      VK_FORMAT_BC1_RGBA_UNORM_BLOCK,    4, 8, false, false, true,  false, false, "", 4},
    {"bc1_rgba_srgb", VK_FORMAT_BC1_RGBA_SRGB_BLOCK,     4, 8, false, false, true,  false, true,  "", 4},
};
// clang-format on
} // namespace

const FormatInfo* find_format(const std::string& name) {
    for (const auto& f : kFormats)
        if (name == f.name) return &f;
    return nullptr;
}

const FormatInfo* find_format(VkFormat vf) {
    for (const auto& f : kFormats)
        if (vf == f.format) return &f;
    return nullptr;
}

std::vector<std::string> format_names() {
    std::vector<std::string> out;
    for (const auto& f : kFormats) out.emplace_back(f.name);
    return out;
}

} // namespace pl::vk
