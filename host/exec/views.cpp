#include "exec/views.hpp"

#include <algorithm>
#include <cmath>

namespace pl::exec {

namespace {

// One use of an image in a run, for the same-level check.
struct Use {
    std::string image;  // the image owning the memory
    Sel sel;
    bool write = false, view = false, layered = false;
    std::string what;   // "target 'hiz'", "binding 'src'"
    SourceLoc loc;
};

struct Resolver {
    const graph::GraphDesc& g;
    const graph::SizeEnv& base;
    const CompiledPass& cp;
    graph::SizeEnv env;

    Error err(const std::string& msg, const SourceLoc& l, const std::string& res) const {
        Error e = make_error(msg, l.known() ? l : cp.desc->loc);
        e.pass = cp.desc->name;
        e.resource = res;
        return e;
    }
    std::string at_run() const {
        std::string s = " at iteration " + std::to_string(env.locals.at("iteration"));
        if (cp.group >= 0 && cp.repeat > 1) s += " of group iteration " + std::to_string(env.locals.at("group_iteration"));
        return s;
    }
    const graph::ImageDesc* base_image(const std::string& n) const {
        const graph::ImageDesc* d = g.find_image(n);
        if (d && !d->alias.empty()) d = g.find_image(d->alias);
        return d;
    }
    int layers_of(const graph::ImageDesc& d) const { return graph::image_layers(g, d); }

    // A mip or layer expression's value, checked against the image's count (0 = unknown).
    Result<int> eval(const graph::SizeExpr& e, const std::string& image, const char* what, int count) const {
        auto v = graph::eval_scalar(e, env);
        if (!v) {
            Error x = v.error();
            x.pass = cp.desc->name;
            x.resource = image;
            return x;
        }
        if (*v < 0 || (count > 0 && *v >= count)) {
            std::string text = e.text.empty() ? std::to_string(*v) : "\"" + e.text + "\"";
            Error x = err(std::string(what) + " = " + text + " is " + std::to_string(*v) + at_run() + "; image '" + image + "' has " +
                              std::to_string(count) + " " + what + (count == 1 ? "" : "s") +
                              (count > 0 ? " (0.." + std::to_string(count - 1) + ")" : ""),
                          e.loc, image);
            x.hint = std::string("the ") + what + " must exist at every iteration: check repeat and the expression";
            return x;
        }
        return static_cast<int>(*v);
    }

    Result<Sel> attachment(const graph::AttachmentRef& a) const {
        Sel s{a.mip, a.layer == -2 ? static_cast<int>(env.locals.at("iteration")) : a.layer};
        const graph::ImageDesc* d = base_image(a.image);
        if (!d) return s;
        if (!a.mip_expr.empty()) {
            auto m = eval(a.mip_expr, a.image, "mip", graph::image_levels(g, *d, env));
            if (!m) return m.error();
            s.mip = *m;
        }
        if (!a.layer_expr.empty()) {
            auto l = eval(a.layer_expr, a.image, "layer", d->kind == graph::ImageKind::tex3d ? 0 : layers_of(*d));
            if (!l) return l.error();
            s.layer = *l;
        }
        return s;
    }

    Result<Sel> view(const BoundResource& b) const {
        Sel s;
        if (!b.view) return s;
        const graph::ImageDesc* d = base_image(b.resource);
        if (!d) return s;
        if (!b.view->mip.empty()) {
            auto m = eval(b.view->mip, b.resource, "mip", graph::image_levels(g, *d, env));
            if (!m) return m.error();
            s.mip = *m;
        }
        if (!b.view->layer.empty()) {
            if (d->kind == graph::ImageKind::tex3d)
                return err("image '" + b.resource + "' is 3D: a view selects a mip, not a layer", b.view->layer.loc, b.resource);
            auto l = eval(b.view->layer, b.resource, "layer", layers_of(*d));
            if (!l) return l.error();
            s.layer = *l;
        }
        return s;
    }

    // Two uses of one image in one run, one of them writing, on overlapping levels and layers:
    // undefined (a feedback loop), unless neither selects a level (the whole-image cases that
    // bind_pass already judges).
    Status same_level(const std::vector<Use>& uses) const {
        auto overlap = [](const Sel& a, const Sel& b) {
            bool mips = a.mip < 0 || b.mip < 0 || a.mip == b.mip;
            bool layers = a.layer < 0 || b.layer < 0 || a.layer == b.layer;
            return mips && layers;
        };
        for (size_t i = 0; i < uses.size(); ++i)
            for (size_t j = i + 1; j < uses.size(); ++j) {
                const Use &a = uses[i], &b = uses[j];
                if (a.image != b.image || !(a.write || b.write) || !(a.view || b.view) || !overlap(a.sel, b.sel)) continue;
                const Use& v = a.view ? a : b;
                const Use& o = a.view ? b : a;
                auto level = [](const Use& u) {
                    return (u.sel.mip < 0 ? std::string("every level") : "level " + std::to_string(u.sel.mip)) +
                           (u.sel.layer < 0 || !u.layered ? "" : " layer " + std::to_string(u.sel.layer));
                };
                Error e = err("image '" + v.image + "': " + v.what + " (" + level(v) + ") and " + o.what + " (" + level(o) +
                                  ") touch the same level" + at_run() + ", and one of them writes it",
                              v.loc, v.image);
                e.notes.push_back(o.what + " is at " + o.loc.str());
                e.hint = "read one level and write another (e.g. sample mip = \"iteration\", render mip = \"iteration + 1\")";
                return e;
            }
        return ok_status();
    }

    Result<RunViews> run(int group_iteration, int iteration) {
        env.locals["group_iteration"] = group_iteration;
        env.locals["iteration"] = iteration;
        const graph::PassDesc& pd = *cp.desc;
        RunViews rv;
        std::vector<Use> uses;
        auto owner = [&](const std::string& n) {
            const graph::ImageDesc* d = base_image(n);
            return d ? d->name : n;
        };
        auto layered = [&](const std::string& n) {
            const graph::ImageDesc* d = base_image(n);
            return d && layers_of(*d) > 1;
        };
        for (const auto& t : pd.targets) {
            auto s = attachment(t);
            if (!s) return s.error();
            rv.targets.push_back(*s);
            uses.push_back({owner(t.image), *s, true, false, layered(t.image), "target '" + t.image + "'", t.loc});
        }
        if (pd.depth) {
            auto s = attachment(pd.depth->target);
            if (!s) return s.error();
            rv.depth = *s;
            uses.push_back({owner(pd.depth->target.image), *s, pd.depth->write, false, layered(pd.depth->target.image),
                            "depth '" + pd.depth->target.image + "'", pd.depth->target.loc});
        }
        for (const auto& b : cp.bindings) {
            auto s = view(b);
            if (!s) return s.error();
            rv.bindings.push_back(*s);
            if (b.kind != BoundResource::Kind::image) continue;
            bool w = b.access == Access::storage_write || b.access == Access::storage_read_write;
            SourceLoc l = pd.keys.at("bind." + b.binding.name, pd.loc);
            uses.push_back({owner(b.resource), *s, w, b.view != nullptr, layered(b.resource), "binding '" + b.binding.name + "'", l});
        }
        if (auto st = same_level(uses); !st) return st.error();
        if (auto st = same_render_area(rv); !st) return st.error();
        return rv;
    }

    // Dynamic rendering has one render area, so every attachment's selected level must have the
    // same size in this run (a target at mip 2 with a depth at mip 3 cannot be drawn). Checked here,
    // per run and at the build's size, so `check` reports it at the attachment's value.
    Status same_render_area(const RunViews& rv) const {
        const graph::PassDesc& pd = *cp.desc;
        struct Area {
            const graph::AttachmentRef* ref;
            int64_t w, h;
        };
        std::vector<Area> areas;
        auto add = [&](const graph::AttachmentRef& a, int mip) {
            const graph::ImageDesc* d = base_image(a.image);
            if (!d) return;
            auto e = graph::image_extent(g, *d, env);
            if (!e) return;  // a file image: its size is known when it is loaded
            const int m = std::max(0, mip);
            areas.push_back({&a, std::max<int64_t>(1, e->w >> m), std::max<int64_t>(1, e->h >> m)});
        };
        for (size_t k = 0; k < pd.targets.size() && k < rv.targets.size(); ++k) add(pd.targets[k], rv.targets[k].mip);
        if (pd.depth) add(pd.depth->target, rv.depth.mip);
        for (const Area& a : areas) {
            const Area& first = areas.front();
            if (a.w == first.w && a.h == first.h) continue;
            auto level = [](const graph::AttachmentRef& r, int64_t w, int64_t h) {
                return "'" + r.image + "' is " + std::to_string(w) + "x" + std::to_string(h);
            };
            const std::string when = cp.repeat > 1 || cp.group >= 0 ? at_run() : "";
            Error e = err("the pass's attachments differ in size" + when + ": " + level(*first.ref, first.w, first.h) + ", " +
                              level(*a.ref, a.w, a.h) + " (one render area covers them all)",
                          a.ref->loc, a.ref->image);
            e.hint = "select levels of the same size (mip) or attachments of the same size";
            return e;
        }
        return ok_status();
    }
};

} // namespace

Status resolve_views(const graph::GraphDesc& g, const graph::SizeEnv& env, CompiledPass& cp, int group_repeat) {
    Resolver r{g, env, cp, env};
    // Inside a group, a pass without a repeat of its own sees the group's iteration as
    // `iteration`; one with its own repeat counts its own iterations (and sees group_iteration).
    const bool own = !cp.desc->repeat.empty();
    const int count = own ? cp.repeat : group_repeat;
    r.env.locals["iteration_count"] = count;
    cp.runs.clear();
    cp.runs.reserve(static_cast<size_t>(group_repeat) * cp.repeat);
    for (int gi = 0; gi < group_repeat; ++gi)
        for (int i = 0; i < cp.repeat; ++i) {
            auto rv = r.run(gi, own ? i : gi);
            if (!rv) return rv.error();
            cp.runs.push_back(std::move(rv.value()));
        }
    return ok_status();
}

} // namespace pl::exec
