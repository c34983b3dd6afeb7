// Procedural textures, so presets need no downloaded assets. Deterministic (integer hash).
#include "image/image.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace pl::image {

namespace {

std::vector<double> arg(const std::map<std::string, std::vector<double>>& a, const std::string& k, std::vector<double> def) {
    auto it = a.find(k);
    return it == a.end() ? def : it->second;
}

uint32_t hash3(int x, int y, int z, uint32_t seed) {
    uint32_t h = static_cast<uint32_t>(x) * 0x8da6b343u ^ static_cast<uint32_t>(y) * 0xd8163841u ^
                 static_cast<uint32_t>(z) * 0xcb1ab31fu ^ seed * 0x165667b1u;
    h ^= h >> 15;
    h *= 0x2c1b3c6du;
    h ^= h >> 12;
    h *= 0x297a2d39u;
    h ^= h >> 15;
    return h;
}

float rnd(int x, int y, int z, uint32_t seed) { return static_cast<float>(hash3(x, y, z, seed) >> 8) / 16777216.0f; }

float fade(float t) { return t * t * (3.0f - 2.0f * t); }

// Tileable with period `p` cells: lattice coordinates wrap.
float value_noise(float x, float y, float z, int p, int pz, uint32_t seed) {
    int xi = static_cast<int>(std::floor(x)), yi = static_cast<int>(std::floor(y)), zi = static_cast<int>(std::floor(z));
    float fx = fade(x - xi), fy = fade(y - yi), fz = fade(z - zi);
    auto w = [&](int a, int m) { return ((a % m) + m) % m; };
    auto v = [&](int dx, int dy, int dz) { return rnd(w(xi + dx, p), w(yi + dy, p), w(zi + dz, pz), seed); };
    auto lerp = [](float a, float b, float t) { return a + (b - a) * t; };
    return lerp(lerp(lerp(v(0, 0, 0), v(1, 0, 0), fx), lerp(v(0, 1, 0), v(1, 1, 0), fx), fy),
                lerp(lerp(v(0, 0, 1), v(1, 0, 1), fx), lerp(v(0, 1, 1), v(1, 1, 1), fx), fy), fz);
}

float gradient_noise(float x, float y, float z, int p, int pz, uint32_t seed) {
    int xi = static_cast<int>(std::floor(x)), yi = static_cast<int>(std::floor(y)), zi = static_cast<int>(std::floor(z));
    float fx = x - xi, fy = y - yi, fz = z - zi;
    auto w = [&](int a, int m) { return ((a % m) + m) % m; };
    auto g = [&](int dx, int dy, int dz) {
        uint32_t h = hash3(w(xi + dx, p), w(yi + dy, p), w(zi + dz, pz), seed);
        float gx = ((h & 0xff) / 127.5f) - 1.0f, gy = (((h >> 8) & 0xff) / 127.5f) - 1.0f, gz = (((h >> 16) & 0xff) / 127.5f) - 1.0f;
        float len = std::sqrt(gx * gx + gy * gy + gz * gz) + 1e-6f;
        return (gx * (fx - dx) + gy * (fy - dy) + gz * (fz - dz)) / len;
    };
    auto q = [](float t) { return t * t * t * (t * (t * 6.0f - 15.0f) + 10.0f); };
    float u = q(fx), v = q(fy), s = q(fz);
    auto lerp = [](float a, float b, float t) { return a + (b - a) * t; };
    return lerp(lerp(lerp(g(0, 0, 0), g(1, 0, 0), u), lerp(g(0, 1, 0), g(1, 1, 0), u), v),
                lerp(lerp(g(0, 0, 1), g(1, 0, 1), u), lerp(g(0, 1, 1), g(1, 1, 1), u), v), s);
}

} // namespace

std::vector<std::string> generator_names() { return {"checker", "uv-grid", "value-noise", "gradient-noise", "constant"}; }

Result<Image> generate_image(const std::string& gen, int w, int h, int d, const std::map<std::string, std::vector<double>>& args) {
    if (w < 1 || h < 1 || d < 1 || w > 16384 || h > 16384 || d > 2048)
        return make_error("generator '" + gen + "': size " + std::to_string(w) + "x" + std::to_string(h) + " is out of range");
    auto names = generator_names();
    if (std::find(names.begin(), names.end(), gen) == names.end()) {
        Error e = make_error("unknown image generator '" + gen + "'");
        std::string near = nearest_name(gen, names);
        if (!near.empty()) e.hint = "did you mean '" + near + "'?";
        e.notes.push_back("generators: checker, uv-grid, value-noise, gradient-noise, constant");
        return e;
    }
    Image img;
    img.width = w;
    img.height = h;
    img.depth = d;
    img.pixels.resize(static_cast<size_t>(w) * h * d * 4);
    int cells = static_cast<int>(arg(args, "cells", {8})[0]);
    if (cells < 1) cells = 1;
    auto ca = arg(args, "color_a", {0.9, 0.9, 0.9, 1}), cb = arg(args, "color_b", {0.1, 0.1, 0.1, 1});
    ca.resize(4, 1.0);
    cb.resize(4, 1.0);
    double freq = arg(args, "frequency", {8})[0];
    int octaves = static_cast<int>(arg(args, "octaves", {1})[0]);
    uint32_t seed = static_cast<uint32_t>(arg(args, "seed", {0})[0]);
    auto value = arg(args, "value", {1, 1, 1, 1});
    value.resize(4, 1.0);
    for (int z = 0; z < d; ++z)
        for (int y = 0; y < h; ++y)
            for (int x = 0; x < w; ++x) {
                float* p = img.at(x, y, z);
                float u = (x + 0.5f) / w, v = (y + 0.5f) / h, s = (z + 0.5f) / d;
                if (gen == "checker") {
                    int c = (x * cells / w) + (y * cells / h) + (d > 1 ? z * cells / d : 0);
                    const auto& col = (c % 2) ? cb : ca;
                    for (int k = 0; k < 4; ++k) p[k] = static_cast<float>(col[k]);
                } else if (gen == "uv-grid") {
                    // Red/green ramps, white grid lines every 1/cells, a bright cell at the origin.
                    float gu = u * cells, gv = v * cells;
                    bool line = std::fabs(gu - std::round(gu)) * w / cells < 1.0f || std::fabs(gv - std::round(gv)) * h / cells < 1.0f;
                    bool origin = gu < 1.0f && gv < 1.0f;
                    p[0] = line ? 1.0f : u;
                    p[1] = line ? 1.0f : v;
                    p[2] = line ? 1.0f : origin ? 1.0f : 0.25f;
                    p[3] = 1.0f;
                } else if (gen == "constant") {
                    for (int k = 0; k < 4; ++k) p[k] = static_cast<float>(value[k]);
                } else {
                    float sum = 0, amp = 1, norm = 0;
                    int period = std::max(1, static_cast<int>(freq));
                    for (int o = 0; o < std::max(1, octaves); ++o) {
                        float n = gen == "value-noise"
                                      ? value_noise(u * period, v * period, s * period, period, d > 1 ? period : 1, seed + o)
                                      : 0.5f + 0.5f * gradient_noise(u * period, v * period, s * period, period, d > 1 ? period : 1, seed + o);
                        sum += amp * n;
                        norm += amp;
                        amp *= 0.5f;
                        period *= 2;
                    }
                    float n = std::clamp(sum / norm, 0.0f, 1.0f);
                    p[0] = p[1] = p[2] = n;
                    p[3] = 1.0f;
                }
            }
    return img;
}

} // namespace pl::image
