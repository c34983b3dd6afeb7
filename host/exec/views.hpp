// Per-run level and layer selections of a pass: `mip = "iteration + 1"` on a target, bind views
// { image, mip, layer }. Evaluated at build time for every run (a repeated pass's iterations, a
// group's iterations), so that a level out of range or a level read and written by one run is an
// error at its TOML value before anything is recorded.
#pragma once

#include "exec/build.hpp"
#include "graph/readable.hpp"

namespace pl::exec {

// Fills cp.runs for every run of the pass; `group_repeat` is its group's count (1 outside one).
Status resolve_views(const graph::GraphDesc& g, const graph::SizeEnv& env, CompiledPass& cp, int group_repeat);

} // namespace pl::exec
