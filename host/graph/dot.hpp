// Graphviz output of a pass graph (`passlab graph PRESET --dot`): passes as boxes, images and
// buffers as ellipses (history resources dashed, the output doubled), edges resource -> pass
// for reads and pass -> resource for writes; a [[group]] is a cluster around its members.
#pragma once

#include "graph/desc.hpp"

namespace pl::graph {

// Reads and writes the description states (targets, depth, resolve, src/dst, image of a
// mips/clear pass, indirect buffers) are always drawn; what the shaders read and write is only
// known after reflection and comes from `io` (one entry per pass, in order) when given. A read
// of NAME_prev is drawn from NAME as a dashed "prev" edge.
std::string to_dot(const GraphDesc& g, const std::vector<PassIO>* io);

} // namespace pl::graph
