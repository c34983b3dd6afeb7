// `simplify = { ratio | triangles, max_error, morph = { ... } }` on a [meshes] entry: what the
// QEM simplifier (scene/simplify.hpp) is asked for. Every value is range-checked here, at its
// TOML location, so nothing about it fails later when the mesh is built.
#include "graph/parse_parts.hpp"

#include <cmath>
#include <cstdio>

namespace pl::graph {

namespace {

std::string num(double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", x);
    return b;
}

// Unknown keys first: a misspelt `ratoi` should be named as such, not as a missing target.
Status parse_level(TableReader& r, SimplifyLevelDesc& l, bool with_morph) {
    std::vector<std::string> keys = {"ratio", "triangles", "max_error"};
    if (with_morph) keys.push_back("morph");
    if (auto s = r.finish(keys); !s) return s;
    if (r.has("ratio")) {
        double x = 0;
        if (auto s = r.number("ratio", x); !s) return s;
        if (!(x > 0 && x <= 1)) return r.error(r.what() + ": ratio must be in (0, 1], not " + num(x), r.value_loc("ratio"));
        l.ratio = x;
    }
    if (r.has("triangles")) {
        int n = 0;
        if (auto s = r.integer("triangles", n, 1, INT32_MAX); !s) return s;
        l.triangles = n;
    }
    if (r.has("max_error")) {
        double x = 0;
        if (auto s = r.number("max_error", x); !s) return s;
        if (!(x >= 0) || !std::isfinite(x))
            return r.error(r.what() + ": max_error must be a finite distance >= 0, not " + num(x), r.value_loc("max_error"));
        l.max_error = x;
    }
    if (l.ratio && l.triangles)
        return r.error(r.what() + ": give ratio or triangles, not both", r.key_loc("triangles"));
    if (!l.ratio && !l.triangles && !l.max_error)
        return r.error(r.what() + " needs a target: ratio, triangles or max_error", r.loc());
    return ok_status();
}

} // namespace

Status parse_mesh_simplify(TableReader& mesh, MeshSimplifyDesc& out) {
    auto t = mesh.table("simplify", "a table { ratio = ... } (or triangles, max_error, morph)");
    if (!t) return t.error();
    TableReader r(**t, mesh.file(), mesh.what() + " simplify", mesh.locs(), "simplify.");
    out.loc = r.loc();
    if (auto s = parse_level(r, out.target, true); !s) return s;
    auto m = r.table("morph", "a table { ratio = ... } (the coarser mesh to morph into)");
    if (!m) return m.error();
    if (*m) {
        TableReader mr(**m, mesh.file(), mesh.what() + " simplify.morph", mesh.locs(), "simplify.morph.");
        SimplifyLevelDesc l;
        if (auto s = parse_level(mr, l, false); !s) return s;
        // The morph target continues the same collapse sequence, so it must be coarser.
        const SimplifyLevelDesc& b = out.target;
        if ((l.ratio && b.ratio && *l.ratio >= *b.ratio) || (l.triangles && b.triangles && *l.triangles >= *b.triangles))
            return mr.error(mr.what() + ": the morph target must be coarser than the mesh (fewer triangles)",
                            mr.value_loc(l.ratio ? "ratio" : "triangles"));
        out.morph = l;
    }
    return ok_status();
}

} // namespace pl::graph
