// Small helpers for walking SPIR-V words, shared by reflection and binding rewriting.
#pragma once

#include <cstdint>
#include <string>
#include <vector>

namespace pl::shader {

// A literal string stored in words [i, end): UTF-8, NUL-terminated, 4 bytes per word (little end).
inline std::string spirv_string(const std::vector<uint32_t>& w, size_t i, size_t end) {
    std::string s;
    for (; i < end; ++i)
        for (int b = 0; b < 4; ++b) {
            char c = static_cast<char>((w[i] >> (8 * b)) & 0xff);
            if (!c) return s;
            s += c;
        }
    return s;
}

} // namespace pl::shader
