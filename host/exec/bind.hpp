// Binding by name: each descriptor a pass's shaders declare is matched to the frame block, the
// params block, or a graph image/buffer of the same name (`<name>_prev` for history). Unknown
// names, type mismatches (storage format, sampler dimension) and feedback loops (sampling an
// image the pass renders into) are user errors pointing at the declaration.
#pragma once

#include "exec/build.hpp"
#include "graph/sizeexpr.hpp"

namespace pl::exec {

Status bind_pass(const graph::GraphDesc& desc, CompiledPass& pass);

// The environment size expressions are evaluated in: view size and param values.
graph::SizeEnv size_env(const graph::GraphDesc& desc, std::array<int, 2> view);

// Finds "file:line:col" of the declaration of the first of `names` found among `files` (the
// first line whose code, comments aside, mentions it together with `uniform` or `buffer`), for
// errors about shader resources.
SourceLoc find_declaration(const std::vector<std::filesystem::path>& files, const std::vector<std::string>& names);

} // namespace pl::exec
