#include "vk/clear_value.hpp"

#include <cmath>
#include <cstdio>
#include <cstdint>
#include <string_view>

namespace pl::vk {
namespace {

// Signedness is not a column of the format table; the names follow Vulkan's suffixes
// ("ui" = UINT, "i" = SINT), and every integer format in the table has one of the two.
bool is_signed(const FormatInfo& f) {
    std::string_view n = f.name;
    return n.size() >= 1 && n.back() == 'i' && !(n.size() >= 2 && n[n.size() - 2] == 'u');
}

int channel_bits(const FormatInfo& f) { return 8 * f.bytes_per_texel / f.components; }

std::string number(double x) {
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.10g", x);  // 4294967295 and 1.5 as written
    return buf;
}

} // namespace

std::string clear_value_problem(const FormatInfo& f, const std::array<double, 4>& v) {
    for (size_t c = 0; c < 4; ++c)
        if (!std::isfinite(v[c])) return "clear component " + std::to_string(c) + " is not a finite number";
    if (!f.is_integer) return "";
    const int bits = channel_bits(f);
    const double lo = is_signed(f) ? -std::ldexp(1.0, bits - 1) : 0.0;
    const double hi = is_signed(f) ? std::ldexp(1.0, bits - 1) - 1.0 : std::ldexp(1.0, bits) - 1.0;
    for (size_t c = 0; c < 4; ++c) {
        if (v[c] != std::floor(v[c]) || v[c] < lo || v[c] > hi)
            return "clear component " + std::to_string(c) + " = " + number(v[c]) + " is not an integer in " +
                   number(lo) + ".." + number(hi) + ", the range of format '" + f.name + "'";
    }
    return "";
}

VkClearColorValue clear_color(const FormatInfo& f, const std::array<double, 4>& v) {
    VkClearColorValue out{};
    for (size_t c = 0; c < 4; ++c) {
        if (!f.is_integer)
            out.float32[c] = static_cast<float>(v[c]);
        else if (is_signed(f))
            out.int32[c] = static_cast<int32_t>(v[c]);
        else
            out.uint32[c] = static_cast<uint32_t>(v[c]);
    }
    return out;
}

std::string fill_value_problem(double v) {
    if (!std::isfinite(v) || v != std::floor(v) || v < 0 || v > 4294967295.0)
        return "a buffer is filled with one 32-bit word: the value must be an integer in 0..4294967295, not " + number(v);
    return "";
}

} // namespace pl::vk
