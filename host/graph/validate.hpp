// Checks a parsed graph before anything is compiled or allocated: names, references, formats,
// kinds, shader files and evaluated sizes, each error at the offending key.
#pragma once

#include "graph/desc.hpp"
#include "graph/sizeexpr.hpp"

namespace pl::graph {

struct ValidateOptions {
    std::vector<std::filesystem::path> search_dirs;  // shader lookup order (preset dir, passes/)
};

Status validate_graph(GraphDesc& g, const ValidateOptions& opt);

std::filesystem::path resolve_shader_path(const std::string& file, const std::vector<std::filesystem::path>& search);

} // namespace pl::graph
