// `passlab graph PRESET --dot`: the pass graph with shader-derived reads and writes.
#include "verbs.hpp"
#include "sources.hpp"

#include "exec/build.hpp"
#include "graph/dot.hpp"

#include <cstdio>

namespace pl::lab {

int graph_dot(const std::string& preset, const CommonOptions& c) {
    auto toml = resolve_source(preset);
    if (!toml) return report(toml.error());
    exec::BuildOptions bo;
    bo.cache_dir = cache_dir(c);
    auto built = exec::build_graph(*toml, bo);
    if (!built) return report(built.error());
    std::vector<graph::PassIO> io;
    for (const auto& p : built->passes) io.push_back(p.io);
    std::fputs(graph::to_dot(built->desc, &io).c_str(), stdout);
    return 0;
}

} // namespace pl::lab
