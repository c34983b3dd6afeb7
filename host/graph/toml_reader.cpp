#include "graph/toml_reader.hpp"

#include <algorithm>

namespace pl::graph {

SourceLoc TableReader::loc_of(const toml::node& n) const {
    const auto& s = n.source();
    return {file_, static_cast<int>(s.begin.line), static_cast<int>(s.begin.column)};
}

SourceLoc TableReader::key_loc(const std::string& key) const {
    for (auto&& [k, v] : t_)
        if (k.str() == key) {
            const auto& s = k.source();
            if (s.begin.line) return {file_, static_cast<int>(s.begin.line), static_cast<int>(s.begin.column)};
            return loc_of(v);
        }
    return loc();
}

Error TableReader::error(const std::string& msg, const SourceLoc& l) const { return make_error(msg, l); }

Error TableReader::type_error(const std::string& key, const std::string& expected) const {
    return error(what_ + ": '" + key + "' must be " + expected, key_loc(key));
}

const toml::node* TableReader::get(const std::string& key) {
    known_.insert(key);
    return t_.get(key);
}

Status TableReader::str(const std::string& key, std::string& out, SourceLoc* where) {
    const toml::node* n = get(key);
    if (!n) return ok_status();
    auto v = n->value<std::string>();
    if (!v || !n->is_string()) return type_error(key, "a string");
    out = *v;
    if (where) *where = loc_of(*n);
    return ok_status();
}

Status TableReader::boolean(const std::string& key, bool& out) {
    const toml::node* n = get(key);
    if (!n) return ok_status();
    if (!n->is_boolean()) return type_error(key, "true or false");
    out = *n->value<bool>();
    return ok_status();
}

Status TableReader::number(const std::string& key, double& out) {
    const toml::node* n = get(key);
    if (!n) return ok_status();
    if (!n->is_number()) return type_error(key, "a number");
    out = *n->value<double>();
    return ok_status();
}

Status TableReader::floats(const std::string& key, float& out) {
    double d = out;
    if (auto s = number(key, d); !s) return s;
    out = static_cast<float>(d);
    return ok_status();
}

Status TableReader::integer(const std::string& key, int& out) {
    const toml::node* n = get(key);
    if (!n) return ok_status();
    if (!n->is_integer()) return type_error(key, "an integer");
    int64_t v = *n->value<int64_t>();
    if (v < INT32_MIN || v > INT32_MAX) return error(what_ + ": '" + key + "' is out of range", key_loc(key));
    out = static_cast<int>(v);
    return ok_status();
}

Status TableReader::numbers(const std::string& key, std::vector<double>& out, size_t min_n, size_t max_n) {
    const toml::node* n = get(key);
    if (!n) return ok_status();
    std::string expected = min_n == max_n ? "an array of " + std::to_string(min_n) + " numbers"
                                          : "an array of " + std::to_string(min_n) + " to " + std::to_string(max_n) + " numbers";
    const toml::array* a = n->as_array();
    if (!a) return type_error(key, expected);
    out.clear();
    for (const auto& e : *a) {
        if (!e.is_number()) return type_error(key, expected);
        out.push_back(*e.value<double>());
    }
    if (out.size() < min_n || out.size() > max_n) return type_error(key, expected);
    return ok_status();
}

Status TableReader::strings(const std::string& key, std::vector<std::string>& out) {
    const toml::node* n = get(key);
    if (!n) return ok_status();
    const toml::array* a = n->as_array();
    if (!a) return type_error(key, "an array of strings");
    out.clear();
    for (const auto& e : *a) {
        if (!e.is_string()) return type_error(key, "an array of strings");
        out.push_back(*e.value<std::string>());
    }
    return ok_status();
}

Status read_size_node(const toml::node& n, const TableReader& r, SizeExpr& out) {
    out.loc = r.loc_of(n);
    if (n.is_string()) {
        out.text = *n.value<std::string>();
        return ok_status();
    }
    if (n.is_integer()) {
        out.literal = {*n.value<int64_t>()};
        return ok_status();
    }
    if (const toml::array* a = n.as_array()) {
        for (const auto& e : *a) {
            if (!e.is_integer()) return r.error("a size is an integer, [w, h], [w, h, d] or an expression string", out.loc);
            out.literal.push_back(*e.value<int64_t>());
        }
        if (out.literal.empty() || out.literal.size() > 3)
            return r.error("a size has 1 to 3 components", out.loc);
        return ok_status();
    }
    return r.error("a size is an integer, [w, h], [w, h, d] or an expression string like \"view/2\"", out.loc);
}

Status TableReader::size(const std::string& key, SizeExpr& out) {
    const toml::node* n = get(key);
    if (!n) return ok_status();
    return read_size_node(*n, *this, out);
}

Status TableReader::choice(const std::string& key, std::string& out, const std::vector<std::string>& allowed) {
    SourceLoc where;
    std::string v = out;
    if (auto s = str(key, v, &where); !s) return s;
    if (!has(key)) return ok_status();
    if (std::find(allowed.begin(), allowed.end(), v) == allowed.end()) {
        Error e = error(what_ + ": '" + key + "' cannot be \"" + v + "\"", where);
        suggest(e, v, allowed, "valid", {}, '"');
        return e;
    }
    out = v;
    return ok_status();
}

Status TableReader::finish(const std::vector<std::string>& also_allowed) {
    std::vector<std::string> valid(known_.begin(), known_.end());
    valid.insert(valid.end(), also_allowed.begin(), also_allowed.end());
    for (auto&& [k, v] : t_) {
        std::string key(k.str());
        if (std::find(valid.begin(), valid.end(), key) != valid.end()) continue;
        Error e = error(what_ + ": unknown key '" + key + "'", key_loc(key));
        suggest(e, key, valid, "keys");
        return e;
    }
    return ok_status();
}

Value to_value(const toml::node& n) {
    if (n.is_boolean()) return *n.value<bool>();
    if (n.is_number()) return *n.value<double>();
    if (n.is_string()) return *n.value<std::string>();
    if (const toml::array* a = n.as_array()) {
        std::vector<double> v;
        for (const auto& e : *a)
            if (e.is_number()) v.push_back(*e.value<double>());
        return v;
    }
    return std::string{};
}

} // namespace pl::graph
