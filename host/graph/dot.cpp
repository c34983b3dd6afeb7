#include "graph/dot.hpp"

#include <set>
#include <sstream>

namespace pl::graph {

std::string to_dot(const GraphDesc& g, const std::vector<PassIO>* io) {
    std::ostringstream s;
    s << "digraph \"" << (g.meta.title.empty() ? g.dir.filename().string() : g.meta.title) << "\" {\n";
    s << "  rankdir=LR;\n  node [fontname=\"Helvetica\"];\n";
    for (const auto& i : g.images)
        s << "  \"" << i.name << "\" [shape=ellipse" << (i.history ? ", style=dashed" : "") << ", label=\"" << i.name
          << "\\n" << (i.alias.empty() ? i.format : "alias of " + i.alias) << "\"];\n";
    for (const auto& b : g.buffers) s << "  \"" << b.name << "\" [shape=cylinder];\n";
    for (size_t k = 0; k < g.passes.size(); ++k) {
        const PassDesc& p = g.passes[k];
        s << "  \"pass:" << p.name << "\" [shape=box, style=filled, fillcolor=\"#dde8ff\", label=\"" << p.name << "\"];\n";
        std::set<std::string> reads, writes;
        for (const auto& t : p.targets) writes.insert(t.image);
        if (p.depth) (p.depth->write ? writes : reads).insert(p.depth->target.image);
        if (!p.dst.empty()) writes.insert(p.dst);
        if (!p.src.empty()) reads.insert(p.src);
        if (!p.image.empty()) writes.insert(p.image);
        if (io && k < io->size()) {
            for (const auto& r : (*io)[k].reads) reads.insert(r);
            for (const auto& w : (*io)[k].writes) writes.insert(w);
        }
        for (const auto& r : reads) s << "  \"" << r << "\" -> \"pass:" << p.name << "\";\n";
        for (const auto& w : writes) s << "  \"pass:" << p.name << "\" -> \"" << w << "\";\n";
    }
    s << "}\n";
    return s.str();
}

} // namespace pl::graph
