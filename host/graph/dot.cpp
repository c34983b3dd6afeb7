#include "graph/dot.hpp"

#include <set>
#include <sstream>

namespace pl::graph {

namespace {

// A double-quoted dot ID: quotes and backslashes escaped, newlines as \n.
std::string q(const std::string& s) {
    std::string out = "\"";
    for (char c : s) {
        if (c == '"' || c == '\\') out += '\\';
        if (c == '\n') {
            out += "\\n";
            continue;
        }
        out += c;
    }
    return out + "\"";
}

std::string size_text(const SizeExpr& e) {
    if (!e.text.empty()) return e.text;
    std::string s;
    for (int64_t v : e.literal) s += (s.empty() ? "" : "x") + std::to_string(v);
    return s;
}


} // namespace

std::string to_dot(const GraphDesc& g, const std::vector<PassIO>* io) {
    std::ostringstream s;
    std::string title = g.meta.title.empty() ? g.dir.filename().string() : g.meta.title;
    s << "digraph " << q(title) << " {\n";
    s << "  rankdir=LR;\n  node [fontname=\"Helvetica\", fontsize=10];\n  edge [fontname=\"Helvetica\", fontsize=9];\n";
    std::set<std::string> declared;
    for (const auto& i : g.images) {
        declared.insert(i.name);
        std::string label = i.name + "\n";
        if (!i.alias.empty()) label += "alias of " + i.alias;
        else if (!i.file.empty()) label += i.file;
        else label += i.format + (i.size.empty() ? std::string(i.generator.empty() ? " view" : "") : " " + size_text(i.size));
        if (!i.generator.empty()) label += "\n" + i.generator;
        s << "  " << q(i.name) << " [shape=ellipse, label=" << q(label) << (i.history ? ", style=dashed" : "")
          << (i.name == g.output ? ", peripheries=2" : "") << "];\n";
    }
    for (const auto& b : g.buffers) {
        declared.insert(b.name);
        std::string label = b.name + "\nbuffer " + (b.generator.empty() ? size_text(b.size) + " B" : b.generator);
        s << "  " << q(b.name) << " [shape=ellipse, label=" << q(label) << ", style=" << (b.history ? "\"dashed,filled\"" : "filled")
          << ", fillcolor=\"#f3f3f3\"];\n";
    }
    for (size_t k = 0; k < g.passes.size(); ++k) {
        const PassDesc& p = g.passes[k];
        std::string pid = "pass:" + p.name;
        s << "  " << q(pid) << " [shape=box, label=" << q(p.name + "\n" + kind_name(p.kind))
          << (p.enabled ? ", style=filled, fillcolor=\"#dde8ff\"" : ", style=dashed, fontcolor=gray") << "];\n";
        std::set<std::string> reads, writes;
        for (const auto& t : p.targets) {
            writes.insert(t.image);
            if (!t.resolve.empty()) writes.insert(t.resolve);
        }
        if (p.depth) {
            if (p.depth->test != "off") reads.insert(p.depth->target.image);
            if (p.depth->write) writes.insert(p.depth->target.image);
        }
        if (!p.src.empty()) reads.insert(p.src);
        if (!p.dst.empty()) writes.insert(p.dst);
        if (!p.image.empty()) writes.insert(p.image);
        if (!p.indirect.empty()) reads.insert(p.indirect);
        if (io && k < io->size()) {
            reads.insert((*io)[k].reads.begin(), (*io)[k].reads.end());
            writes.insert((*io)[k].writes.begin(), (*io)[k].writes.end());
        }
        for (const auto& r : reads) {
            if (declared.count(r)) {
                s << "  " << q(r) << " -> " << q(pid) << ";\n";
            } else if (r.size() > 5 && r.compare(r.size() - 5, 5, "_prev") == 0 && declared.count(r.substr(0, r.size() - 5))) {
                s << "  " << q(r.substr(0, r.size() - 5)) << " -> " << q(pid) << " [style=dashed, label=\"prev\"];\n";
            }
        }
        for (const auto& w : writes)
            if (declared.count(w)) s << "  " << q(pid) << " -> " << q(w) << ";\n";
    }
    // A [[group]] as a cluster around its members, labelled with its repeat count (and the
    // order its members run in, which need not be file order).
    for (const auto& gr : g.groups) {
        std::string order;
        for (const auto& m : gr.passes) order += (order.empty() ? "" : ", ") + m;
        std::string repeat = gr.repeat.empty() ? "1" : size_text(gr.repeat);
        s << "  subgraph " << q("cluster_group_" + gr.name) << " {\n    label=" << q("group " + gr.name + ", repeat " + repeat + ": " + order)
          << ";\n    style=rounded;\n";
        for (const auto& m : gr.passes) s << "    " << q("pass:" + m) << ";\n";
        s << "  }\n";
    }
    s << "}\n";
    return s.str();
}

} // namespace pl::graph
