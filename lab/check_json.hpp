// `passlab check --json FILE`: what a checked preset declares, for editors and tools — its
// passes (kind, shaders, reads, writes), images (kind, format, size at the view), buffers, the
// params with the widget the live lab's panel shows for each, and the [[test]] names.
#pragma once

#include "exec/build.hpp"

#include <nlohmann/json_fwd.hpp>

namespace pl::lab {

nlohmann::ordered_json describe_graph(const exec::CompiledGraph& g);

// The panel widget of a param (lab/panel.cpp's param_widget draws exactly these).
const char* widget_kind(const graph::ParamDesc& p);

} // namespace pl::lab
