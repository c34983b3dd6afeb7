// Single-token mutations of GLSL source, for `passlab mutate`: the deliberate breaks a preset
// author would try by hand (docs/test-strength.md: an invariant is trusted once it has been seen to fail on a
// broken formula), generated systematically so that every case's power can be measured.
//
// Each mutant changes one place: an operator swapped, a comparison flipped, min and max swapped,
// a normalize() or clamp() dropped, a constant nudged, a swizzle reversed, a boolean inverted.
// Comments, preprocessor lines (#include, #define, #version ...) and layout(...) qualifiers are
// never touched: mutating them breaks the build, not the formula.
#pragma once

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace pl::mutate {

struct Mutant {
    std::string op;           // short name of the operator, e.g. "+ -> -", "drop normalize"
    size_t offset = 0;        // byte range of the source that is replaced
    size_t length = 0;
    std::string replacement;  // what replaces it
    int line = 1, col = 1;    // 1-based position of `offset`
};

// Every mutant the source offers, in source order.
std::vector<Mutant> find_mutants(std::string_view src);

// The source with one mutant applied.
std::string apply_mutant(std::string_view src, const Mutant& m);

// The source line holding the mutant, before and after (for reports), without the newline.
std::string line_of(std::string_view src, const Mutant& m);
std::string mutated_line_of(std::string_view src, const Mutant& m);

// A deterministic choice of `count` of `n` indices, by seed: the same on every machine and
// standard library (splitmix64 and Fisher-Yates; std::shuffle's algorithm is unspecified).
std::vector<size_t> choose(size_t n, size_t count, uint64_t seed);

} // namespace pl::mutate
