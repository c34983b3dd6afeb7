#include "graph/toml_reader.hpp"

#include <algorithm>
#include <cmath>

namespace pl::graph {

std::string type_name(const toml::node& n) {
    switch (n.type()) {
    case toml::node_type::string: return "a string";
    case toml::node_type::integer: return "an integer";
    case toml::node_type::floating_point: return "a float";
    case toml::node_type::boolean: return "a boolean";
    case toml::node_type::array: return "an array";
    case toml::node_type::table: return "a table";
    case toml::node_type::date:
    case toml::node_type::time:
    case toml::node_type::date_time: return "a date/time";
    case toml::node_type::none: break;
    }
    return "nothing";
}

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

SourceLoc TableReader::value_loc(const std::string& key) const {
    if (const toml::node* n = t_.get(key)) return loc_of(*n);
    return loc();
}

Error TableReader::error(const std::string& msg, const SourceLoc& l) const { return make_error(msg, l); }

Error TableReader::type_error(const std::string& key, const std::string& expected) const {
    std::string found;
    if (const toml::node* n = t_.get(key)) found = ", not " + type_name(*n);
    return error(what_ + ": '" + key + "' must be " + expected + found, value_loc(key));
}

const toml::node* TableReader::get(const std::string& key) {
    known_.insert(key);
    const toml::node* n = t_.get(key);
    if (n && locs_) locs_->map[prefix_ + key] = loc_of(*n);
    return n;
}

Result<const toml::table*> TableReader::table(const std::string& key, const std::string& expected) {
    const toml::node* n = get(key);
    if (!n) return static_cast<const toml::table*>(nullptr);
    if (!n->is_table()) return type_error(key, expected);
    return n->as_table();
}

Status TableReader::str(const std::string& key, std::string& out, SourceLoc* where) {
    const toml::node* n = get(key);
    if (!n) return ok_status();
    if (!n->is_string()) return type_error(key, "a string");
    out = *n->value<std::string>();
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

Status TableReader::number(const std::string& key, double& out, bool allow_inf) {
    const toml::node* n = get(key);
    if (!n) return ok_status();
    if (!n->is_number()) return type_error(key, "a number");
    double v = *n->value<double>();
    if (std::isnan(v) || (!allow_inf && std::isinf(v)))
        return error(what_ + ": '" + key + "' must be a finite number, not " + (std::isnan(v) ? "nan" : v > 0 ? "inf" : "-inf"),
                     value_loc(key));
    out = v;
    return ok_status();
}

Status TableReader::floats(const std::string& key, float& out, bool allow_inf) {
    double d = out;
    if (auto s = number(key, d, allow_inf); !s) return s;
    out = static_cast<float>(d);
    return ok_status();
}

Status TableReader::integer(const std::string& key, int& out, int64_t lo, int64_t hi) {
    const toml::node* n = get(key);
    if (!n) return ok_status();
    if (!n->is_integer()) return type_error(key, "an integer");
    int64_t v = *n->value<int64_t>();
    if (v < lo || v > hi)
        return error(what_ + ": '" + key + "' is " + std::to_string(v) + "; it must be between " + std::to_string(lo) +
                         " and " + std::to_string(hi),
                     value_loc(key));
    out = static_cast<int>(v);
    return ok_status();
}

Status TableReader::uinteger(const std::string& key, uint32_t& out, int64_t hi) {
    const toml::node* n = get(key);
    if (!n) return ok_status();
    if (!n->is_integer()) return type_error(key, "an integer");
    int64_t v = *n->value<int64_t>();
    if (v < 0 || v > hi)
        return error(what_ + ": '" + key + "' is " + std::to_string(v) + "; it must be between 0 and " + std::to_string(hi),
                     value_loc(key));
    out = static_cast<uint32_t>(v);
    return ok_status();
}

namespace {
std::string count_text(size_t min_n, size_t max_n, const char* what) {
    if (min_n == max_n) return "an array of " + std::to_string(min_n) + " " + what;
    return "an array of " + std::to_string(min_n) + " to " + std::to_string(max_n) + " " + what;
}
} // namespace

Status TableReader::numbers(const std::string& key, std::vector<double>& out, size_t min_n, size_t max_n) {
    const toml::node* n = get(key);
    if (!n) return ok_status();
    std::string expected = count_text(min_n, max_n, "numbers");
    const toml::array* a = n->as_array();
    if (!a) return type_error(key, expected);
    std::vector<double> v;
    for (const auto& e : *a) {
        if (!e.is_number()) return error(what_ + ": '" + key + "' must be " + expected + "; an element is " + type_name(e), loc_of(e));
        v.push_back(*e.value<double>());
        if (!std::isfinite(v.back())) return error(what_ + ": '" + key + "' must be finite numbers; an element is " + (std::isnan(v.back()) ? "nan" : "infinite"), loc_of(e));
    }
    if (v.size() < min_n || v.size() > max_n)
        return error(what_ + ": '" + key + "' must be " + expected + ", not " + std::to_string(v.size()), value_loc(key));
    out = std::move(v);
    return ok_status();
}

Status TableReader::integers(const std::string& key, std::vector<int64_t>& out, size_t min_n, size_t max_n) {
    const toml::node* n = get(key);
    if (!n) return ok_status();
    std::string expected = count_text(min_n, max_n, "integers");
    const toml::array* a = n->as_array();
    if (!a) return type_error(key, expected);
    std::vector<int64_t> v;
    for (const auto& e : *a) {
        if (!e.is_integer()) return error(what_ + ": '" + key + "' must be " + expected + "; an element is " + type_name(e), loc_of(e));
        v.push_back(*e.value<int64_t>());
    }
    if (v.size() < min_n || v.size() > max_n)
        return error(what_ + ": '" + key + "' must be " + expected + ", not " + std::to_string(v.size()), value_loc(key));
    out = std::move(v);
    return ok_status();
}

Status TableReader::strings(const std::string& key, std::vector<std::string>& out) {
    const toml::node* n = get(key);
    if (!n) return ok_status();
    const toml::array* a = n->as_array();
    if (!a) return type_error(key, "an array of strings");
    std::vector<std::string> v;
    for (const auto& e : *a) {
        if (!e.is_string()) return error(what_ + ": '" + key + "' must be an array of strings; an element is " + type_name(e), loc_of(e));
        v.push_back(*e.value<std::string>());
    }
    out = std::move(v);
    return ok_status();
}

Status read_size_node(const toml::node& n, const TableReader& r, SizeExpr& out) {
    out = {};
    out.loc = r.loc_of(n);
    const char* expected = "a size is an integer, [w, h], [w, h, d] or an expression string like \"view/2\"";
    if (n.is_string()) {
        out.text = *n.value<std::string>();
        if (out.text.find_first_not_of(" \t") == std::string::npos) return r.error("the size expression is empty", out.loc);
        return ok_status();
    }
    if (n.is_integer()) {
        out.literal = {*n.value<int64_t>()};
        return ok_status();
    }
    if (const toml::array* a = n.as_array()) {
        for (const auto& e : *a) {
            if (!e.is_integer()) return r.error(std::string(expected) + "; an element is " + type_name(e), r.loc_of(e));
            out.literal.push_back(*e.value<int64_t>());
        }
        if (out.literal.empty() || out.literal.size() > 3)
            return r.error("a size has 1 to 3 components, not " + std::to_string(out.literal.size()), out.loc);
        return ok_status();
    }
    return r.error(std::string(expected) + ", not " + type_name(n), out.loc);
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

Result<Value> to_value(const toml::node& n, const TableReader& r, const std::string& key) {
    if (n.is_boolean()) return Value{*n.value<bool>()};
    if (n.is_number()) return Value{*n.value<double>()};
    if (n.is_string()) return Value{*n.value<std::string>()};
    if (const toml::array* a = n.as_array()) {
        std::vector<double> v;
        for (const auto& e : *a) {
            if (!e.is_number()) return r.error(r.what() + ": '" + key + "': an array value holds numbers only, not " + type_name(e), r.loc_of(e));
            v.push_back(*e.value<double>());
        }
        return Value{std::move(v)};
    }
    return r.error(r.what() + ": '" + key + "' must be a number, a bool, a string or an array of numbers, not " + type_name(n), r.loc_of(n));
}

} // namespace pl::graph
