// Checks on a buffer read back after the last frame (`buffer = "NAME"` in a check): elements are
// selected by `index` or `range = [first, count]` (default: all), each element is `stride` bytes
// (default 4) and its value is the 32-bit word at byte `field` of it, decoded as `type` (uint,
// int or float; default float). Integers are compared exactly.
// Kinds: probe, no_nan, range, mean, sorted, sum, count.
#pragma once

#include "check/agreement.hpp"
#include "check/args.hpp"
#include "check/checks.hpp"
#include "graph/sizeexpr.hpp"

#include <cstdint>
#include <vector>

namespace pl::check {

enum class WordType { uint, sint, f32 };

struct Selection {
    size_t first = 0, count = 0;  // elements
    size_t stride = 4, field = 0;  // bytes
    WordType type = WordType::f32;
    std::string label;  // "buffer 'nodes'[0..15] field 4 (stride 16, uint)"
};

// The elements a check selects from a buffer of `words`; an error when they lie outside it.
Result<Selection> select(const Args& a, size_t words);
// The selected values: exact for 32-bit integers (doubles hold them exactly).
std::vector<double> decode(const std::vector<uint32_t>& words, const Selection& s);

// Evaluates a buffer check on `words`; `env` evaluates an `expect` expression ("view.w*view.h").
CheckResult buffer_property(const std::vector<uint32_t>& words, const graph::CheckDesc& c, const graph::SizeEnv& env);

// `reduction`: every selected element equals `op` (min, max or sum) of channel `of_channel` of the
// image `of` over the pixels `mask` counts, reduced here on the host: exactly (min and max of
// floats are exact; a float sum may differ by `tol`), integers exactly.
CheckResult buffer_reduction(const std::vector<uint32_t>& words, const graph::CheckDesc& c, const image::Image& of, const Mask& mask);

} // namespace pl::check
