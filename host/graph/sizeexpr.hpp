// Size expressions: "view", "view/2", "view.w*view.h*4", "ceil_div(view, 8)", [w,h], 256.
// Values are integer vectors of 1-3 components; `view` is the 2-vector (w, h); scalars
// broadcast; + - * / % and unary minus with the usual precedence; / and % floor (so that
// a == (a / b) * b + a % b for negative values too); comparisons == != < <= > >= bind loosest and
// give 1 or 0 (a vector compares per component), and an enum param compares with an option's
// name in quotes, "params.show == 'taa'", so `enabled` needs no arithmetic on option indices;
// min, max and ceil_div take two arguments,
// log2 one (floor(log2(x)) for x >= 1, so "log2(max(view.w, view.h))" counts the halvings of a
// full mip chain).
// Errors point at the offending token: the SizeExpr's loc is the start of the TOML value (the
// opening quote), so the column of a token is loc.col + 1 + its offset in the string.
// Float expressions (camera eye/target/fov ...) use the same grammar over doubles: decimal
// numbers, real division, vector params as vectors (`params.dir * 10`, `params.dir.y`), and
// sin cos tan sqrt abs radians normalize.
#pragma once

#include "graph/desc.hpp"

#include <map>

namespace pl::graph {

struct SizeEnv {
    int64_t view_w = 640, view_h = 360;
    std::map<std::string, double> params;  // params.NAME (truncated toward zero)
    // Names that only some expressions see: `iteration`, `iteration_count` and
    // `group_iteration` in a pass's mip/layer selections (exec/views.cpp).
    std::map<std::string, int64_t> locals;
    std::map<std::string, std::vector<double>> vectors;  // float expressions: every component
    std::map<std::string, std::vector<std::string>> options;  // enum params: option names, by index
};

struct Extent {
    int64_t w = 1, h = 1, d = 1;
};

Result<std::vector<int64_t>> eval_size(const SizeExpr& e, const SizeEnv& env);
// A single number (buffer bytes, repeat counts); a vector is an error.
Result<int64_t> eval_scalar(const SizeExpr& e, const SizeEnv& env);
// dims 2 or 3: a scalar means a square (256 -> 256x256) or a cube; a 2-vector in 3D gets
// depth 1; a 3-vector in 2D is an error.
Result<Extent> eval_extent(const SizeExpr& e, const SizeEnv& env, int dims);

// The names an expression may use in `env` (for messages and docs).
std::vector<std::string> size_names(const SizeEnv& env);

// A float expression: 1..4 components, finite.
Result<std::vector<double>> eval_floats(const FloatExpr& e, const SizeEnv& env);
std::vector<std::string> float_names(const SizeEnv& env);

} // namespace pl::graph
