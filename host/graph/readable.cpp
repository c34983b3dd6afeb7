#include "graph/readable.hpp"

#include <algorithm>
#include <cmath>

namespace pl::graph {

namespace {

const ImageDesc& storage_of(const GraphDesc& g, const ImageDesc& d) {
    if (!d.alias.empty())
        if (const ImageDesc* t = g.find_image(d.alias)) return *t;
    return d;
}

} // namespace

uint32_t full_mip_count(uint32_t w, uint32_t h, uint32_t d) {
    return 1 + static_cast<uint32_t>(std::floor(std::log2(std::max({w, h, d, 1u}))));
}

std::optional<Extent> image_extent(const GraphDesc& g, const ImageDesc& d_in, const SizeEnv& env) {
    const ImageDesc& d = storage_of(g, d_in);
    if (!d.file.empty()) return std::nullopt;
    SizeExpr size = d.size;
    if (size.empty()) {
        if (d.generator.empty()) size.text = "view";
        else size.literal = {256, 256};
    }
    auto ext = eval_extent(size, env, d.kind == ImageKind::tex3d ? 3 : 2);
    if (!ext) return std::nullopt;
    return *ext;
}

int image_levels(const GraphDesc& g, const ImageDesc& d_in, const SizeEnv& env) {
    const ImageDesc& d = storage_of(g, d_in);
    auto ext = image_extent(g, d, env);
    if (!ext) return d.mips == 0 ? 0 : d.mips;  // a file decides, or reported by size validation
    uint32_t full = full_mip_count(static_cast<uint32_t>(std::max<int64_t>(1, ext->w)), static_cast<uint32_t>(std::max<int64_t>(1, ext->h)),
                                   static_cast<uint32_t>(std::max<int64_t>(1, ext->d)));
    return static_cast<int>(d.mips == 0 ? full : std::min(static_cast<uint32_t>(d.mips), full));
}

int image_layers(const GraphDesc& g, const ImageDesc& d_in) {
    const ImageDesc& d = storage_of(g, d_in);
    return d.kind == ImageKind::cube ? 6 : d.kind == ImageKind::tex2d_array ? std::max(1, d.layers) : 1;
}

size_t buffer_elements(size_t bytes, size_t stride, size_t field) {
    return bytes >= field + 4 ? (bytes - field - 4) / stride + 1 : 0;
}

} // namespace pl::graph
