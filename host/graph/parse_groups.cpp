// [[group]]: passes repeated together. Only read and typed here; whether the passes exist, sit in
// one group only and the swap images exist is validate_groups' job (it sees the whole graph).
#include "graph/parse_parts.hpp"

namespace pl::graph {

Status parse_group(const toml::table& t, const std::string& file, GraphDesc& g) {
    GroupDesc gr;
    TableReader r(t, file, "[[group]]", &gr.keys);
    gr.loc = r.loc();
    if (auto s = r.str("name", gr.name); !s) return s;
    if (gr.name.empty()) return r.error("[[group]] needs name = \"...\"", gr.loc);
    if (!is_identifier(gr.name))
        return r.error("group name '" + gr.name + "' must be an identifier (letters, digits, _)", r.value_loc("name"));
    gr.loc = r.key_loc("name");
    if (auto s = unique_name(r, g.groups, "group", gr.name, gr.loc); !s) return s;
    const std::string what = "group '" + gr.name + "'";
    if (auto s = r.size("repeat", gr.repeat); !s) return s;
    if (gr.repeat.literal.size() > 1)
        return r.error(what + ": repeat is a count (an integer or an expression), not a vector", gr.repeat.loc);
    if (const toml::node* n = r.get("passes")) {
        const toml::array* a = n->as_array();
        if (!a) return r.type_error("passes", "an array of pass names");
        for (const auto& e : *a) {
            if (!e.is_string()) return r.error(what + ": passes holds pass names (strings), not " + type_name(e), r.loc_of(e));
            gr.keys.map["passes." + std::to_string(gr.passes.size())] = r.loc_of(e);
            gr.passes.push_back(*e.value<std::string>());
        }
    }
    if (gr.passes.empty()) return r.error(what + " needs passes = [\"a\", \"b\", ...] (run in that order)", gr.loc);
    if (auto s = r.strings("swap", gr.swap); !s) return s;
    if (gr.swap.size() % 2) return r.error(what + ": swap lists pairs of images: an even number of names", r.value_loc("swap"));
    if (auto s = r.finish(); !s) return s;
    g.groups.push_back(std::move(gr));
    return ok_status();
}

} // namespace pl::graph
