// Size expressions: "view", "view/2", "view.w*view.h*4", "ceil_div(view.w, 8)", [w,h], 256.
// Values are integer vectors of 1-3 components; scalars broadcast; division floors.
#pragma once

#include "graph/desc.hpp"

#include <map>

namespace pl::graph {

struct SizeEnv {
    int64_t view_w = 640, view_h = 360;
    std::map<std::string, double> params;  // params.NAME (truncated to integer)
};

struct Extent {
    int64_t w = 1, h = 1, d = 1;
};

Result<std::vector<int64_t>> eval_size(const SizeExpr& e, const SizeEnv& env);
Result<int64_t> eval_scalar(const SizeExpr& e, const SizeEnv& env);
// dims 2 or 3: a scalar means a square/cube; a 2-vector in 3D gets depth 1.
Result<Extent> eval_extent(const SizeExpr& e, const SizeEnv& env, int dims);

} // namespace pl::graph
