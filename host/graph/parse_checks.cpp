// The checks of a [[test]] (`probes = [...]`, `checks = [...]`), parsed strictly: each kind has
// its own keys, every key is type- and range-checked at its value, and unknown keys and kinds are
// errors with a "did you mean". A check looks at an image (`pass`, default the test's) or, with
// `buffer = "NAME"`, at typed elements of a buffer. check/ evaluates what is parsed here.
#include "graph/parse_parts.hpp"

#include <algorithm>
#include <cmath>

namespace pl::graph {

namespace {

enum class T {
    number,    // any number
    nonneg,    // number >= 0
    unit,      // number in [0, 1]
    index,     // integer >= 0
    count,     // integer >= 1
    stride,    // integer >= 4, a multiple of 4 (bytes)
    name,      // string naming an image, buffer or param (validate.cpp checks the name)
    boolean,
    channel,   // integer 0..3
    channels,  // 1..4 integers 0..3
    pair,      // [first >= 0, count >= 1]
    point,     // [x, y]
    numbers,   // array of numbers
    expect,    // number, array of numbers, or (buffers) a size expression string
    any,       // number, bool, string or numbers (matches_variant's value)
    choice,
};

struct Key {
    const char* name;
    T type;
    std::vector<std::string> choices = {};
};

std::vector<Key> join(std::vector<Key> a, const std::vector<Key>& b) {
    a.insert(a.end(), b.begin(), b.end());
    return a;
}

// `mip` and `layer` pick one level and layer of the image (default: the case's).
const std::vector<Key> kImageSelect = {{"pass", T::name}, {"channel", T::channel}, {"channels", T::channels},
                                       {"mip", T::index}, {"layer", T::index}};
const std::vector<Key> kBufferSelect = {{"buffer", T::name}, {"index", T::index}, {"range", T::pair},
                                        {"type", T::choice, {"uint", "int", "float"}}, {"stride", T::stride},
                                        {"field", T::index}};
// Partial agreement: only the pixels where `mask`'s channel is nonzero count, and a `fraction`
// of them must pass.
const std::vector<Key> kMask = {{"mask", T::name}, {"mask_channel", T::channel}, {"invert_mask", T::boolean}};
const std::vector<Key> kPartial = join({{"fraction", T::unit}}, kMask);

struct Kind {
    const char* name;
    std::vector<Key> image;   // keys on an image (besides kImageSelect); empty with !on_image
    std::vector<Key> buffer;  // keys on a buffer (besides kBufferSelect); empty with !on_buffer
    bool on_image = true, on_buffer = false;
};

const std::vector<Kind>& kinds() {
    static const std::vector<Kind> k = {
        {"probe", {{"uv", T::point}, {"px", T::point}, {"expect", T::numbers}, {"tol", T::nonneg}},
         {{"expect", T::expect}, {"tol", T::nonneg}}, true, true},
        {"no_nan", {}, {}, true, true},
        {"range", join({{"min", T::number}, {"max", T::number}}, kPartial), {{"min", T::number}, {"max", T::number}}, true, true},
        {"mean", {{"expect", T::number}, {"tol", T::nonneg}}, {{"expect", T::number}, {"tol", T::nonneg}}, true, true},
        {"symmetry", {{"axis", T::choice, {"x", "y"}}, {"tol", T::nonneg}}, {}},
        {"white_furnace", {{"expect", T::number}, {"tol", T::nonneg}}, {}},
        {"matches_pass", join({{"other", T::name}, {"tol", T::nonneg}, {"rmse", T::nonneg}}, kPartial), {}},
        {"matches_variant", {{"param", T::name}, {"value", T::any}, {"tol", T::nonneg}}, {}},
        {"stable", {{"tol", T::nonneg}}, {}},
        {"order_independent", {{"tol", T::nonneg}}, {}},
        {"monotone", {{"param", T::name}, {"values", T::numbers}, {"direction", T::choice, {"increasing", "decreasing"}}, {"tol", T::nonneg}}, {}},
        {"sorted", {}, {{"group", T::count}, {"order", T::choice, {"ascending", "descending"}}, {"tol", T::nonneg}}, false, true},
        {"sum", {}, {{"expect", T::expect}, {"tol", T::nonneg}}, false, true},
        {"count", {}, {{"value", T::number}, {"min", T::number}, {"max", T::number}, {"expect", T::expect}}, false, true},
        // The selected elements equal a reduction of an image's channel computed on the host.
        {"reduction", {}, join({{"of", T::name}, {"op", T::choice, {"min", "max", "sum"}}, {"of_channel", T::channel}, {"tol", T::nonneg}}, kMask), false, true},
    };
    return k;
}

std::vector<std::string> names_of(const std::vector<Key>& keys) {
    std::vector<std::string> n;
    for (const auto& k : keys) n.push_back(k.name);
    return n;
}

// Longer spellings people write for a key; edit distance alone would not suggest these.
const std::vector<std::pair<std::string, std::string>> kSynonyms = {
    {"tolerance", "tol"}, {"minimum", "min"}, {"maximum", "max"}, {"image", "pass"}, {"offset", "field"},
    {"element", "index"}, {"elements", "range"}, {"expected", "expect"}, {"threshold", "tol"}};

bool is_int(double x) { return std::isfinite(x) && x == std::floor(x); }

// Reads one key into c.args after checking its type and range.
Status read_arg(TableReader& r, const Key& k, const toml::node& n, CheckDesc& c) {
    const std::string key = k.name;
    auto bad = [&](const std::string& why) { return r.error(r.what() + ": '" + key + "' " + why, r.loc_of(n)); };
    auto number = [&](double& x) -> Status {
        if (!n.is_number()) return r.type_error(key, "a number");
        x = *n.value<double>();
        return ok_status();
    };
    auto ints = [&](size_t lo_n, size_t hi_n, std::vector<int64_t>& v) { return r.integers(key, v, lo_n, hi_n); };
    double x = 0;
    std::vector<int64_t> iv;
    switch (k.type) {
    case T::number:
        if (auto s = number(x); !s) return s;
        break;
    case T::nonneg:
        if (auto s = number(x); !s) return s;
        if (!(x >= 0)) return bad("must be >= 0");
        break;
    case T::unit:
        if (auto s = number(x); !s) return s;
        if (!(x >= 0 && x <= 1)) return bad("must be a fraction in [0, 1]");
        break;
    case T::index:
    case T::count:
    case T::channel:
    case T::stride: {
        int v = 0;
        int64_t lo = k.type == T::count ? 1 : k.type == T::stride ? 4 : 0, hi = k.type == T::channel ? 3 : INT32_MAX;
        if (auto s = r.integer(key, v, lo, hi); !s) return s;
        if ((k.type == T::stride) && v % 4) return bad("must be a multiple of 4 bytes (buffers hold 32-bit words)");
        break;
    }
    case T::name:
    case T::choice: {
        std::string s;
        if (k.type == T::choice) {
            if (auto st = r.choice(key, s, k.choices); !st) return st;
        } else {
            if (auto st = r.str(key, s); !st) return st;
            if (s.empty()) return bad("must name something, not \"\"");
        }
        break;
    }
    case T::boolean: {
        bool b = false;
        if (auto s = r.boolean(key, b); !s) return s;
        break;
    }
    case T::channels:
        if (auto s = ints(1, 4, iv); !s) return s;
        for (int64_t ch : iv)
            if (ch < 0 || ch > 3) return bad("holds channel " + std::to_string(ch) + "; channels are 0..3 (r, g, b, a)");
        break;
    case T::pair:
        if (auto s = ints(2, 2, iv); !s) return s;
        if (iv[0] < 0 || iv[1] < 1) return bad("is [first element >= 0, count >= 1]");
        break;
    case T::point: {
        std::vector<double> v;
        if (auto s = r.numbers(key, v, 2, 2); !s) return s;
        break;
    }
    case T::numbers: {
        std::vector<double> v;
        if (auto s = r.numbers(key, v, 1, size_t(1) << 16); !s) return s;
        break;
    }
    case T::expect:
        if (n.is_string() || n.is_number()) break;
        if (n.is_array()) {
            std::vector<double> v;
            if (auto s = r.numbers(key, v, 1, size_t(1) << 16); !s) return s;
            break;
        }
        return r.type_error(key, "a number, an array of numbers or an expression string (\"view.w*view.h\")");
    case T::any:
        break;
    }
    r.get(key);  // record its location
    auto value = to_value(n, r, key);
    if (!value) return value.error();
    c.args[key] = *value;
    return ok_status();
}

// Rules between keys of one check, after each key is known to be well-formed.
Status check_combination(TableReader& r, CheckDesc& c, bool on_buffer) {
    auto has = [&](const char* k) { return c.args.count(k) > 0; };
    auto num = [&](const char* k, double def) {
        auto it = c.args.find(k);
        return it == c.args.end() ? def : std::get<double>(it->second);
    };
    auto at = [&](const char* k) { return r.value_loc(k); };
    const std::string& kind = c.kind;
    const std::string w = r.what() + " (" + kind + ")";
    if (on_buffer) {
        std::string type = has("type") ? std::get<std::string>(c.args["type"]) : "float";
        bool integer = type != "float";
        double stride = num("stride", 4), field = num("field", 0);
        if (has("field") && (static_cast<int64_t>(field) % 4 || field >= stride))
            return r.error(w + ": field is a byte offset inside the element: a multiple of 4 below stride " + std::to_string(int(stride)), at("field"));
        if (has("index") && has("range")) return r.error(w + ": give index = N or range = [first, count], not both", at("range"));
        if (kind == "probe" && !has("index") && !has("range"))
            return r.error(w + " needs index = N or range = [first, count] (elements of buffer '" + std::get<std::string>(c.args["buffer"]) + "')", c.loc);
        if (integer && has("tol") && kind != "mean")
            return r.error(w + ": type = \"" + type + "\" values are compared exactly; remove tol (or decode as type = \"float\")", at("tol"));
        if (kind == "no_nan" && integer) return r.error(w + ": " + type + " values cannot be NaN; no_nan needs type = \"float\"", at("type"));
        if ((kind == "probe" || kind == "sum" || kind == "count") && !has("expect"))
            return r.error(w + " needs expect = ...", c.loc);
        if (kind == "range" && !has("min") && !has("max")) return r.error(w + " needs min and/or max", c.loc);
        if (kind == "reduction" && (!has("of") || !has("op")))
            return r.error(w + " needs of = \"IMAGE\" and op = \"min\" | \"max\" | \"sum\" (what the elements must equal)", c.loc);
        if (kind == "reduction" && (has("mask_channel") || has("invert_mask")) && !has("mask")) {
            const char* k = has("mask_channel") ? "mask_channel" : "invert_mask";
            return r.error(w + ": " + k + " describes a mask; add mask = \"IMAGE\"", r.key_loc(k));
        }
        if (kind == "count" && has("value") && (has("min") || has("max")))
            return r.error(w + ": counts elements equal to value, or within min..max, not both", at("value"));
        if (kind == "count" && !has("value") && !has("min") && !has("max"))
            return r.error(w + " needs value = X (or min/max): which elements to count", c.loc);
        // Integer expectations must be integers of the type, so a typo cannot silently never match.
        auto it = c.args.find("expect");
        if (it != c.args.end() && (integer || kind == "count")) {
            std::vector<double> v;
            if (auto d = std::get_if<double>(&it->second)) v = {*d};
            if (auto a = std::get_if<std::vector<double>>(&it->second)) v = *a;
            // probe: a 32-bit value of the type; sum: a 64-bit total (negative only for int);
            // count: a number of elements.
            double lo = type == "int" ? (kind == "probe" ? -2147483648.0 : kind == "sum" ? -9.0e18 : 0.0) : 0.0;
            double hi = kind == "probe" ? (type == "int" ? 2147483647.0 : 4294967295.0) : 9.0e18;
            for (double x : v)
                if (!is_int(x) || x < lo || x > hi) {
                    char b[64];
                    std::snprintf(b, sizeof b, "%.17g", x);
                    return r.error(w + ": expect value " + b + " is not " + (kind == "probe" ? "a 32-bit " + type : kind == "sum" ? "an integer sum of " + type + " values" : "a count"), at("expect"));
                }
        }
        if (it != c.args.end() && std::holds_alternative<std::vector<double>>(it->second) && kind != "probe")
            return r.error(w + ": expect is one number here", at("expect"));
        if (it != c.args.end() && std::holds_alternative<std::vector<double>>(it->second) && has("index") &&
            std::get<std::vector<double>>(it->second).size() != 1)
            return r.error(w + ": index = N selects one element; expect one value (or use range = [first, count])", at("expect"));
        if (it != c.args.end() && has("range")) {
            size_t n = static_cast<size_t>(std::get<std::vector<double>>(c.args["range"])[1]);
            if (auto a = std::get_if<std::vector<double>>(&it->second); a && a->size() != 1 && a->size() != n)
                return r.error(w + ": expect has " + std::to_string(a->size()) + " values for " + std::to_string(n) +
                                   " elements; give one (all equal) or one per element", at("expect"));
        }
        return ok_status();
    }
    if (kind == "probe") {
        if (has("uv") == has("px")) return r.error(r.what() + " needs exactly one of uv = [u, v] (0..1) or px = [x, y]", c.loc);
        if (!has("expect")) return r.error(r.what() + " needs expect = [1 to 4 values]", c.loc);
        if (std::get<std::vector<double>>(c.args["expect"]).size() > 4)
            return r.error(r.what() + ": expect has at most 4 values (r, g, b, a)", at("expect"));
    }
    if (kind == "matches_pass" && !has("other")) return r.error(w + " needs other = \"IMAGE\"", c.loc);
    if (kind == "matches_variant" && (!has("param") || !has("value"))) return r.error(w + " needs param = \"name\" and value = ...", c.loc);
    if (kind == "monotone") {
        if (!has("param")) return r.error(w + " needs param = \"name\"", c.loc);
        if (!has("values") || std::get<std::vector<double>>(c.args["values"]).size() < 2)
            return r.error(w + " needs values = [at least 2 numbers]", has("values") ? at("values") : c.loc);
    }
    if ((has("mask_channel") || has("invert_mask")) && !has("mask")) {
        const char* k = has("mask_channel") ? "mask_channel" : "invert_mask";
        return r.error(w + ": " + k + " describes a mask; add mask = \"IMAGE\"", r.key_loc(k));
    }
    return ok_status();
}

} // namespace

Status parse_check(const toml::table& t, TableReader& owner, CheckDesc& c, const char* forced_kind) {
    TableReader r(t, owner.file(), owner.what() + (forced_kind ? " probe" : " check"), &c.keys);
    c.loc = r.loc();
    std::vector<std::string> kind_names;
    for (const auto& k : kinds()) kind_names.push_back(k.name);
    if (forced_kind) {
        c.kind = forced_kind;
        if (r.has("kind")) return r.error(r.what() + ": probes = [...] holds probes; write kind in checks = [...]", r.key_loc("kind"));
    } else {
        if (!r.has("kind")) return r.error(r.what() + " needs kind = \"...\" (probe, no_nan, range, mean, sorted, sum, ...)", c.loc);
        if (auto s = r.choice("kind", c.kind, kind_names); !s) return s;
    }
    const Kind& kind = *std::find_if(kinds().begin(), kinds().end(), [&](const Kind& k) { return c.kind == k.name; });
    const bool on_buffer = r.has("buffer");
    const std::string buffer_name = on_buffer && t["buffer"].is_string() ? *t["buffer"].value<std::string>() : "";
    if (on_buffer && !kind.on_buffer)
        return r.error(r.what() + ": " + c.kind + " checks images; it has no buffer = (buffer checks: probe, no_nan, range, mean, sorted, sum, count, reduction)",
                       r.key_loc("buffer"));
    if (!on_buffer && !kind.on_image)
        return r.error(r.what() + ": " + c.kind + " checks a buffer: add buffer = \"NAME\"", c.loc);
    std::vector<Key> keys = on_buffer ? join(kBufferSelect, kind.buffer) : join(kImageSelect, kind.image);
    for (auto&& [k, v] : t) {
        std::string key(k.str());
        if (key == "kind") continue;
        auto spec = std::find_if(keys.begin(), keys.end(), [&](const Key& s) { return key == s.name; });
        if (spec == keys.end()) {
            Error e = r.error(r.what() + " (" + c.kind + "): unknown key '" + key + "'", r.key_loc(key));
            auto valid = names_of(keys);
            auto other = names_of(on_buffer ? kImageSelect : kBufferSelect);
            if (std::find(other.begin(), other.end(), key) != other.end())
                e.hint = on_buffer ? "'" + key + "' selects image pixels; this check reads buffer '" + buffer_name + "'"
                                   : "'" + key + "' selects buffer elements; add buffer = \"NAME\"";
            else
                suggest(e, key, valid, "keys");
            for (const auto& [wrong, right] : kSynonyms)
                if (key == wrong && std::find(valid.begin(), valid.end(), right) != valid.end()) e.hint = "did you mean '" + right + "'?";
            return e;
        }
        if (auto s = read_arg(r, *spec, v, c); !s) return s;
    }
    return check_combination(r, c, on_buffer);
}

} // namespace pl::graph
