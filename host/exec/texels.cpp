#include "exec/texels.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace pl::exec {

float half_to_float(uint16_t h) {
    uint32_t sign = (h >> 15) & 1, exp = (h >> 10) & 0x1f, mant = h & 0x3ff;
    float v;
    if (exp == 0) v = std::ldexp(static_cast<float>(mant), -24);
    else if (exp == 31) v = mant ? NAN : INFINITY;
    else v = std::ldexp(static_cast<float>(mant | 0x400), static_cast<int>(exp) - 25);
    return sign ? -v : v;
}

uint16_t float_to_half(float f) {
    uint32_t x;
    std::memcpy(&x, &f, 4);
    uint32_t sign = (x >> 16) & 0x8000;
    if (std::isnan(f)) return static_cast<uint16_t>(sign | 0x7e00);
    float a = std::fabs(f);
    if (a >= 65520.0f) return static_cast<uint16_t>(sign | 0x7c00);
    if (a < 6.103515625e-05f) {  // subnormal half
        return static_cast<uint16_t>(sign | static_cast<uint32_t>(std::nearbyint(a * 16777216.0f)));
    }
    int e;
    float m = std::frexp(a, &e);  // a = m * 2^e, m in [0.5,1)
    uint32_t mant = static_cast<uint32_t>(std::nearbyint((m * 2.0f - 1.0f) * 1024.0f));
    uint32_t exp = static_cast<uint32_t>(e - 1 + 15);
    if (mant == 1024) {
        mant = 0;
        ++exp;
    }
    return static_cast<uint16_t>(sign | (exp << 10) | mant);
}

namespace {
uint8_t unorm8(float v) { return static_cast<uint8_t>(std::lround(std::clamp(v, 0.0f, 1.0f) * 255.0f)); }
int8_t snorm8(float v) { return static_cast<int8_t>(std::lround(std::clamp(v, -1.0f, 1.0f) * 127.0f)); }
} // namespace

uint32_t copy_texel_size(const vk::FormatInfo& f) {
    switch (f.format) {
    case VK_FORMAT_D24_UNORM_S8_UINT: return 4;  // depth aspect copies as 32-bit words
    case VK_FORMAT_D32_SFLOAT_S8_UINT: return 4;
    default: return static_cast<uint32_t>(f.bytes_per_texel);
    }
}

bool encode_texel(const vk::FormatInfo& f, const float c[4], uint8_t* out) {
    int n = f.components;
    switch (f.format) {
    case VK_FORMAT_R8_UNORM:
    case VK_FORMAT_R8G8_UNORM:
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:  // values are already sRGB-encoded when srgb = true
        for (int i = 0; i < n; ++i) out[i] = unorm8(c[i]);
        return true;
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
        out[0] = unorm8(c[2]), out[1] = unorm8(c[1]), out[2] = unorm8(c[0]), out[3] = unorm8(c[3]);
        return true;
    case VK_FORMAT_R8G8B8A8_SNORM:
        for (int i = 0; i < 4; ++i) out[i] = static_cast<uint8_t>(snorm8(c[i]));
        return true;
    case VK_FORMAT_R16_SFLOAT:
    case VK_FORMAT_R16G16_SFLOAT:
    case VK_FORMAT_R16G16B16A16_SFLOAT:
        for (int i = 0; i < n; ++i) {
            uint16_t h = float_to_half(c[i]);
            std::memcpy(out + 2 * i, &h, 2);
        }
        return true;
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32G32_SFLOAT:
    case VK_FORMAT_R32G32B32A32_SFLOAT:
    case VK_FORMAT_D32_SFLOAT: std::memcpy(out, c, 4 * static_cast<size_t>(n)); return true;
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_R32G32_UINT:
    case VK_FORMAT_R32G32B32A32_UINT:
        for (int i = 0; i < n; ++i) {
            uint32_t v = static_cast<uint32_t>(std::max(0.0f, c[i]));
            std::memcpy(out + 4 * i, &v, 4);
        }
        return true;
    case VK_FORMAT_R32_SINT:
    case VK_FORMAT_R32G32B32A32_SINT:
        for (int i = 0; i < n; ++i) {
            int32_t v = static_cast<int32_t>(c[i]);
            std::memcpy(out + 4 * i, &v, 4);
        }
        return true;
    default: return false;
    }
}

bool decode_texel(const vk::FormatInfo& f, const uint8_t* in, float c[4], bool depth_copy) {
    c[0] = c[1] = c[2] = 0.0f;
    c[3] = 1.0f;
    int n = f.components;
    if (depth_copy || f.is_depth) {
        switch (f.format) {
        case VK_FORMAT_D16_UNORM: {
            uint16_t v;
            std::memcpy(&v, in, 2);
            c[0] = v / 65535.0f;
            return true;
        }
        case VK_FORMAT_D24_UNORM_S8_UINT: {
            uint32_t v;
            std::memcpy(&v, in, 4);
            c[0] = static_cast<float>(v & 0xffffff) / 16777215.0f;
            return true;
        }
        case VK_FORMAT_D32_SFLOAT:
        case VK_FORMAT_D32_SFLOAT_S8_UINT: std::memcpy(&c[0], in, 4); return true;
        default: return false;
        }
    }
    switch (f.format) {
    case VK_FORMAT_R8_UNORM:
    case VK_FORMAT_R8G8_UNORM:
    case VK_FORMAT_R8G8B8A8_UNORM:
    case VK_FORMAT_R8G8B8A8_SRGB:
        for (int i = 0; i < n; ++i) c[i] = in[i] / 255.0f;
        return true;
    case VK_FORMAT_B8G8R8A8_UNORM:
    case VK_FORMAT_B8G8R8A8_SRGB:
        c[0] = in[2] / 255.0f, c[1] = in[1] / 255.0f, c[2] = in[0] / 255.0f, c[3] = in[3] / 255.0f;
        return true;
    case VK_FORMAT_R8G8B8A8_SNORM:
        for (int i = 0; i < 4; ++i) c[i] = std::max(-1.0f, static_cast<int8_t>(in[i]) / 127.0f);
        return true;
    case VK_FORMAT_A2B10G10R10_UNORM_PACK32: {
        uint32_t v;
        std::memcpy(&v, in, 4);
        c[0] = (v & 0x3ff) / 1023.0f, c[1] = ((v >> 10) & 0x3ff) / 1023.0f;
        c[2] = ((v >> 20) & 0x3ff) / 1023.0f, c[3] = ((v >> 30) & 3) / 3.0f;
        return true;
    }
    case VK_FORMAT_B10G11R11_UFLOAT_PACK32: {
        uint32_t v;
        std::memcpy(&v, in, 4);
        // 11/10-bit floats: 5-bit exponent like half, 6/5-bit mantissa without sign.
        auto small = [](uint32_t bits, int mant_bits) {
            uint32_t e = bits >> mant_bits, m = bits & ((1u << mant_bits) - 1);
            return half_to_float(static_cast<uint16_t>((e << 10) | (m << (10 - mant_bits))));
        };
        c[0] = small(v & 0x7ff, 6), c[1] = small((v >> 11) & 0x7ff, 6), c[2] = small(v >> 22, 5);
        return true;
    }
    case VK_FORMAT_R16_SFLOAT:
    case VK_FORMAT_R16G16_SFLOAT:
    case VK_FORMAT_R16G16B16A16_SFLOAT:
        for (int i = 0; i < n; ++i) {
            uint16_t h;
            std::memcpy(&h, in + 2 * i, 2);
            c[i] = half_to_float(h);
        }
        return true;
    case VK_FORMAT_R32_SFLOAT:
    case VK_FORMAT_R32G32_SFLOAT:
    case VK_FORMAT_R32G32B32A32_SFLOAT: std::memcpy(c, in, 4 * static_cast<size_t>(n)); return true;
    case VK_FORMAT_R32_UINT:
    case VK_FORMAT_R32G32_UINT:
    case VK_FORMAT_R32G32B32A32_UINT:
        for (int i = 0; i < n; ++i) {
            uint32_t v;
            std::memcpy(&v, in + 4 * i, 4);
            c[i] = static_cast<float>(v);
        }
        return true;
    case VK_FORMAT_R16G16B16A16_UINT:
        for (int i = 0; i < 4; ++i) {
            uint16_t v;
            std::memcpy(&v, in + 2 * i, 2);
            c[i] = static_cast<float>(v);
        }
        return true;
    case VK_FORMAT_R32_SINT:
    case VK_FORMAT_R32G32B32A32_SINT:
        for (int i = 0; i < n; ++i) {
            int32_t v;
            std::memcpy(&v, in + 4 * i, 4);
            c[i] = static_cast<float>(v);
        }
        return true;
    default: return false;
    }
}

} // namespace pl::exec
