// [params]: NAME = value or NAME = { value, min, max, log, color, options, doc, type }.
// The type comes from the value (float, int, bool, 2..4 numbers, string with options) unless
// `type` says otherwise; a declared type that disagrees with the value is an error rather than a
// silent conversion, because the shader's std140 block is generated from it.
#include "graph/parse_parts.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <set>

namespace pl::graph {

namespace {

const std::vector<std::string> kTypeNames = {"float", "int", "bool", "vec2", "vec3", "vec4", "color3", "color4", "enum"};

std::string num_text(double x) {
    char b[32];
    std::snprintf(b, sizeof b, "%g", x);
    return b;
}

// What a value looks like, for "declared X but the value is Y".
std::string value_kind(const toml::node& v) {
    if (const toml::array* a = v.as_array()) return "an array of " + std::to_string(a->size());
    return type_name(v);
}

struct ParamReader {
    ParamDesc& p;
    SourceLoc value_loc;

    Error err(const std::string& msg, const SourceLoc& l) const {
        Error e = make_error("param '" + p.name + "': " + msg, l);
        e.resource = p.name;
        return e;
    }

    // Fills p.type and p.value from the value node and the declared type (may be empty).
    Status value(const toml::node& v, const std::string& declared, bool color) {
        if (!declared.empty()) return typed(v, declared, color);
        if (v.is_boolean()) return typed(v, "bool", color);
        if (v.is_integer()) return typed(v, "int", color);
        if (v.is_floating_point()) return typed(v, "float", color);
        if (v.is_string()) {
            if (p.options.empty())
                return err("a string value needs options = [\"a\", \"b\", ...] (an enum)", value_loc);
            return typed(v, "enum", color);
        }
        if (const toml::array* a = v.as_array()) {
            size_t n = a->size();
            if (n < 2 || n > 4) return err("a vector value has 2 to 4 numbers, not " + std::to_string(n), value_loc);
            if (color && n == 2) return err("color = true needs 3 or 4 numbers", value_loc);
            std::string t = color ? "color" + std::to_string(n) : "vec" + std::to_string(n);
            return typed(v, t, color);
        }
        return err("the value must be a number, true/false, 2 to 4 numbers or an option string, not " + type_name(v), value_loc);
    }

    Status typed(const toml::node& v, const std::string& t, bool color) {
        auto mismatch = [&] { return err("declared " + t + " but the value is " + value_kind(v), value_loc); };
        if (color && t != "color3" && t != "color4" && t.rfind("vec", 0) != 0)
            return err("color = true applies to 3- or 4-component vectors, not " + t, value_loc);
        if (t == "float") {
            if (!v.is_number()) return mismatch();
            p.type = ParamType::f32;
            p.value[0] = *v.value<double>();
        } else if (t == "int") {
            if (!v.is_number()) return mismatch();
            double d = *v.value<double>();
            if (d != std::floor(d) || std::fabs(d) > 2147483647.0)
                return err("declared int but the value " + num_text(d) + " is not a 32-bit integer", value_loc);
            p.type = ParamType::i32;
            p.value[0] = d;
        } else if (t == "bool") {
            if (!v.is_boolean()) return mismatch();
            p.type = ParamType::boolean;
            p.value[0] = *v.value<bool>() ? 1 : 0;
        } else if (t == "enum") {
            if (!v.is_string()) return mismatch();
            if (p.options.empty()) return err("an enum needs options = [\"a\", \"b\", ...]", value_loc);
            std::string sv = *v.value<std::string>();
            auto it = std::find(p.options.begin(), p.options.end(), sv);
            if (it == p.options.end()) {
                Error e = err("value \"" + sv + "\" is not one of its options", value_loc);
                suggest(e, sv, p.options, "options", {}, '"');
                return e;
            }
            p.type = ParamType::enumeration;
            p.value[0] = static_cast<double>(it - p.options.begin());
        } else {  // vec2..vec4, color3, color4
            size_t n = static_cast<size_t>(t.back() - '0');
            const toml::array* a = v.as_array();
            if (!a || a->size() != n) return mismatch();
            for (size_t i = 0; i < n; ++i) {
                if (!(*a)[i].is_number()) return err("declared " + t + " but an element is " + type_name((*a)[i]), value_loc);
                p.value[i] = *(*a)[i].value<double>();
            }
            bool is_color = t.rfind("color", 0) == 0 || color;
            p.type = n == 2 ? ParamType::vec2
                   : n == 3 ? (is_color ? ParamType::color3 : ParamType::vec3)
                            : (is_color ? ParamType::color4 : ParamType::vec4);
        }
        if (!p.options.empty() && p.type != ParamType::enumeration)
            return err("options = [...] make an enum: the value must be one of them (a string)", value_loc);
        return ok_status();
    }

    Status range(const TableReader* r) {
        // TOML has nan and inf; NaN passed every min/max comparison (all are false with it).
        if (p.min && !std::isfinite(*p.min)) return err("min must be a finite number, not " + num_text(*p.min), r ? r->value_loc("min") : p.loc);
        if (p.max && !std::isfinite(*p.max)) return err("max must be a finite number, not " + num_text(*p.max), r ? r->value_loc("max") : p.loc);
        for (int c = 0; c < p.components(); ++c)
            if (!std::isfinite(p.value[static_cast<size_t>(c)]))
                return err("value must be finite, not " + num_text(p.value[static_cast<size_t>(c)]), value_loc);
        if (p.min && p.max && *p.min > *p.max)
            return err("min " + num_text(*p.min) + " is greater than max " + num_text(*p.max), r ? r->value_loc("max") : p.loc);
        if ((p.min || p.max) && (p.type == ParamType::boolean || p.type == ParamType::enumeration))
            return err("min/max apply to numbers and vectors, not to a " +
                           std::string(p.type == ParamType::boolean ? "bool" : "enum"),
                       r ? r->value_loc(p.min ? "min" : "max") : p.loc);
        for (int c = 0; c < p.components(); ++c) {
            double v = p.value[static_cast<size_t>(c)];
            if (p.min && v < *p.min) return err("value " + num_text(v) + " is below its min " + num_text(*p.min), value_loc);
            if (p.max && v > *p.max) return err("value " + num_text(v) + " is above its max " + num_text(*p.max), value_loc);
        }
        return ok_status();
    }
};

Status parse_param(const toml::node& v, const TableReader& sec, const std::string& file, ParamDesc& p) {
    ParamReader pr{p, sec.loc_of(v)};
    const toml::table* pt = v.as_table();
    if (!pt) {
        p.keys.map["value"] = pr.value_loc;
        return pr.value(v, "", false);
    }
    TableReader r(*pt, file, "param '" + p.name + "'", &p.keys);
    const toml::node* value = r.get("value");
    if (!value) return r.error("param '" + p.name + "' needs value = ...", p.loc);
    pr.value_loc = r.loc_of(*value);
    double mn = 0, mx = 0;
    if (r.has("min")) {
        if (auto s = r.number("min", mn); !s) return s;
        p.min = mn;
    }
    if (r.has("max")) {
        if (auto s = r.number("max", mx); !s) return s;
        p.max = mx;
    }
    bool color = false;
    std::string type;
    if (auto s = r.boolean("log", p.log); !s) return s;
    if (auto s = r.boolean("color", color); !s) return s;
    if (auto s = r.strings("options", p.options); !s) return s;
    if (auto s = r.str("doc", p.doc); !s) return s;
    if (auto s = r.choice("type", type, kTypeNames); !s) return s;
    static const std::vector<std::string> kClocks = {"date", "date-month1"};
    if (auto s = r.choice("clock", p.clock, kClocks); !s) return s;
    if (auto s = r.finish(); !s) return s;
    std::set<std::string> seen, seen_upper;
    for (const auto& o : p.options) {
        // Each option becomes a define NAME_OPTION in the shaders.
        if (!is_identifier(o)) return pr.err("option \"" + o + "\" must be an identifier (it becomes a #define)", r.value_loc("options"));
        if (!seen.insert(o).second) return pr.err("option \"" + o + "\" is listed twice", r.value_loc("options"));
        // In capitals: two options that differ only in case would define the same macro twice
        // (an error inside the preamble, far from here).
        std::string upper;
        for (char c : o) upper += static_cast<char>(std::toupper(static_cast<unsigned char>(c)));
        if (!seen_upper.insert(upper).second)
            return pr.err("options \"" + o + "\" and another differ only in case; both would be #define " + upper, r.value_loc("options"));
    }
    if (auto s = pr.value(*value, type, color); !s) return s;
    if (!p.clock.empty() && p.type != ParamType::vec4)
        return pr.err("clock = \"" + p.clock + "\" fills year, month, day and seconds: the param must be a vec4", r.value_loc("clock"));
    if (p.log && p.type != ParamType::f32 && p.type != ParamType::i32)
        return pr.err("log = true applies to a float or int slider", r.value_loc("log"));
    return pr.range(&r);
}

} // namespace

Status parse_params(const toml::table& t, const std::string& file, GraphDesc& g) {
    TableReader sec(t, file, "[params]");
    for (auto&& [k, v] : t) {
        ParamDesc p;
        p.name = std::string(k.str());
        if (auto s = check_name(sec, p.name, "param"); !s) return s;
        p.loc = sec.key_loc(p.name);
        if (auto s = parse_param(v, sec, file, p); !s) {
            if (s.error().resource.empty()) s.error().resource = p.name;
            return s;
        }
        g.params.push_back(std::move(p));
    }
    return ok_status();
}

} // namespace pl::graph
