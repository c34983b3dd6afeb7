// Params with `clock = "date" | "date-month1"` follow the wall clock in `run` (Shadertoy's
// iDate, ISF's DATE): the lab sets them to the local date it started at, and the shader adds
// the lab's time, so the clock runs. Headless verbs never call this: their renders repeat.
#pragma once

#include "graph/desc.hpp"

#include <ctime>
#include <string>
#include <vector>

namespace pl::lab {

// Sets every clock param not given on the command line (`cli_sets`, "name=value") to the local
// date of `start`. Returns how many it set.
int apply_wall_clock(std::vector<graph::ParamDesc>& params, const std::vector<std::string>& cli_sets, std::time_t start);

} // namespace pl::lab
