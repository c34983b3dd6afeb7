// preset.toml -> GraphDesc with source locations (see parse.cpp, parse_resources.cpp,
// parse_passes.cpp).
#pragma once

#include "graph/desc.hpp"

#include <string_view>

namespace pl::graph {

Result<GraphDesc> parse_graph_file(const std::filesystem::path& toml_file);
Result<GraphDesc> parse_graph_text(std::string_view text, const std::filesystem::path& as_file);

} // namespace pl::graph
