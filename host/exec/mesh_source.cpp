#include "exec/mesh_source.hpp"

#include <chrono>

namespace pl::exec {

namespace {

scene::SimplifyTarget target_of(const graph::SimplifyLevelDesc& l) {
    scene::SimplifyTarget t;
    t.ratio = l.ratio;
    if (l.triangles) t.triangles = static_cast<size_t>(*l.triangles);
    t.max_error = l.max_error;
    return t;
}

} // namespace

scene::SimplifyOptions simplify_options(const graph::MeshSimplifyDesc& d) {
    scene::SimplifyOptions o;
    o.target = target_of(d.target);
    if (d.morph) o.morph = target_of(*d.morph);
    return o;
}

Result<CpuMesh> load_graph_mesh(const graph::GraphDesc& g, const graph::MeshDesc& md) {
    Result<scene::Mesh> mesh = md.file.empty() ? scene::generate_mesh(md.generator, md.args) : scene::load_mesh(g.dir / md.file);
    if (!mesh) {
        Error e = mesh.error();
        if (!e.loc.known()) e.loc = md.loc;
        e.resource = md.name;
        return e;
    }
    CpuMesh out;
    if (!md.simplify) {
        out.mesh = std::move(*mesh);
        return out;
    }
    auto t0 = std::chrono::steady_clock::now();
    scene::Simplified s = scene::simplify(*mesh, simplify_options(*md.simplify));
    out.simplify_ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    out.mesh = std::move(s.mesh);
    out.morph = std::move(s.morph);
    out.simplified = s.stats;
    if (out.mesh.indices.empty()) {  // cannot happen with a target >= 1 triangle; kept as a located error
        Error e = make_error("mesh '" + md.name + "': simplification left no triangles", md.simplify->loc);
        e.resource = md.name;
        return e;
    }
    return out;
}

} // namespace pl::exec
