// Graphviz output of a pass graph: passes as boxes, images/buffers as ellipses.
#pragma once

#include "graph/desc.hpp"

namespace pl::graph {

std::string to_dot(const GraphDesc& g, const std::vector<PassIO>* io);

} // namespace pl::graph
