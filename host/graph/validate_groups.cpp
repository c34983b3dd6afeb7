// [[group]] checks: every member is a pass, listed once in one group; swap images exist. Cycles
// through a group (a pass outside it between two members) are found by the planner, which
// orders each group as one unit.
#include "graph/validate_parts.hpp"

#include <algorithm>
#include <map>

namespace pl::graph {

Status validate_groups(const GraphDesc& g, const DeclaredNames& names) {
    std::vector<std::string> pass_names;
    for (const auto& p : g.passes) pass_names.push_back(p.name);
    std::map<std::string, const GroupDesc*> owner;  // pass -> the group that lists it
    for (const auto& gr : g.groups) {
        auto err = [&](const std::string& msg, const SourceLoc& l, const std::string& pass = {}) {
            Error e = make_error("group '" + gr.name + "': " + msg, l.known() ? l : gr.loc);
            e.pass = pass;
            return e;
        };
        for (size_t k = 0; k < gr.passes.size(); ++k) {
            const std::string& n = gr.passes[k];
            SourceLoc l = gr.keys.at("passes." + std::to_string(k), gr.keys.at("passes", gr.loc));
            const PassDesc* p = g.find_pass(n);
            if (!p) {
                Error e = ref_error("pass", n, l, "", pass_names, "passes");
                e.message = "group '" + gr.name + "': " + e.message;
                e.resource.clear();
                if (std::any_of(g.groups.begin(), g.groups.end(), [&](const GroupDesc& o) { return o.name == n; }))
                    e.hint = "'" + n + "' is a group; groups do not nest: list its passes here instead";
                return e;
            }
            if (std::find(gr.passes.begin(), gr.passes.begin() + static_cast<long>(k), n) != gr.passes.begin() + static_cast<long>(k))
                return err("lists pass '" + n + "' twice; a group runs each member once per iteration", l, n);
            auto [it, fresh] = owner.emplace(n, &gr);
            if (!fresh) {
                Error e = err("pass '" + n + "' is already in group '" + it->second->name + "'; a pass belongs to one group", l, n);
                e.notes.push_back("group '" + it->second->name + "' is at " + it->second->loc.str());
                return e;
            }
            if (p->bake) return err("pass '" + n + "' is baked (bake = true): it runs once, so it cannot repeat in a group", l, n);
            for (const auto& s : p->swap)
                if (std::find(gr.swap.begin(), gr.swap.end(), s) != gr.swap.end())
                    return err("image '" + s + "' is swapped both by the group and by its pass '" + n +
                                   "'; swap it in one place",
                               p->swap_loc, n);
        }
        SourceLoc swap_loc = gr.keys.at("swap", gr.loc);
        for (size_t k = 0; k < gr.swap.size(); ++k) {
            if (!g.find_image(gr.swap[k])) {
                Error e = ref_error("swap image", gr.swap[k], swap_loc, "", names.images, "images");
                e.message = "group '" + gr.name + "': " + e.message;
                return e;
            }
            if (k % 2 && gr.swap[k] == gr.swap[k - 1]) return err("swap pairs image '" + gr.swap[k] + "' with itself", swap_loc);
        }
        if (!gr.swap.empty() && gr.repeat.empty()) return err("swap exchanges images between iterations; add repeat = N", swap_loc);
    }
    return ok_status();
}

} // namespace pl::graph
