// How much of an image or a buffer there is to read at one view size: an image's mip levels and
// layers, a buffer's elements of a given stride. Shared by the executor (mip/layer selections of
// passes), the test runner (buffer checks) and validation, which reports a test that reads a
// level, layer or element that does not exist at its TOML value before anything is rendered.
#pragma once

#include "graph/sizeexpr.hpp"

#include <cstddef>
#include <cstdint>
#include <optional>

namespace pl::graph {

// 1 + floor(log2(largest side)): the length of a full mip chain.
uint32_t full_mip_count(uint32_t w, uint32_t h, uint32_t d);
// The size of an image's level 0 at `env`; none for file images (the file decides) and sizes
// that do not evaluate (reported by size validation).
std::optional<Extent> image_extent(const GraphDesc& g, const ImageDesc& d, const SizeEnv& env);
// The levels an image will have (its `mips`, or the full chain of its evaluated size; an alias
// has its target's); 0 when unknown before loading (file images with mips = "full").
int image_levels(const GraphDesc& g, const ImageDesc& d, const SizeEnv& env);
// Its layers: 6 for a cube, `layers` for a 2D array, 1 otherwise (a 3D image's depth is not layers).
int image_layers(const GraphDesc& g, const ImageDesc& d);
// The elements of `stride` bytes whose 32-bit word at byte `field` lies inside a buffer of `bytes`.
size_t buffer_elements(size_t bytes, size_t stride, size_t field);

} // namespace pl::graph
