// [[test]]: test cases for `passlab test`. Its probes and checks are parsed by parse_checks.cpp;
// check/ evaluates them.
#include "graph/parse_parts.hpp"

#include <cmath>
#include <algorithm>

namespace pl::graph {

namespace {

// The keys of a [[test]]'s `tolerance` table: bounds on the golden comparison (docs/format.md).
const std::vector<std::string> kGoldenTolerances = {"rmse", "max_bad_fraction", "bad_threshold", "max_abs", "ssim"};

// cameras = { sun = { eye = [...] } }: each names a camera of [cameras]; its keys are read over
// a copy of that camera, so what is absent keeps the graph's values.
Status parse_test_cameras(TableReader& r, const std::string& file, const GraphDesc& g, TestDesc& d) {
    auto cams = r.table("cameras", "a table { NAME = { eye = [...], ... } }");
    if (!cams) return cams.error();
    if (!*cams) return ok_status();
    TableReader names_r(**cams, file, r.what() + " cameras");
    for (auto&& [k, v] : **cams) {
        std::string name(k.str());
        const CameraDesc* base = g.find_camera(name);
        if (!base) {
            std::vector<std::string> names;
            for (const auto& c : g.cameras) names.push_back(c.name);
            Error e = r.error(r.what() + ": camera '" + name + "' does not exist", names_r.key_loc(name));
            suggest(e, name, names, "cameras", "the graph declares no [cameras]");
            return e;
        }
        const toml::table* ct = v.as_table();
        if (!ct) return r.error(r.what() + ": cameras." + name + " must be a table { eye = [...], ... }, not " + type_name(v), r.loc_of(v));
        CameraDesc c = *base;
        TableReader cr(*ct, file, r.what() + " camera '" + name + "'", &c.keys);
        if (auto s = parse_camera(cr, c); !s) return s;
        d.cameras[name] = std::move(c);
    }
    return ok_status();
}

Status parse_test_body(const toml::table& t, const std::string& file, GraphDesc& g, TestDesc& d) {
    std::string what = "[[test]]";
    if (const toml::node* n = t.get("name"); n && n->is_string()) what = "test '" + *n->value<std::string>() + "'";
    TableReader r(t, file, what, &d.keys);
    d.loc = r.loc();
    if (auto s = r.str("name", d.name); !s) return s;
    if (d.name.empty()) return r.error("[[test]] needs name = \"...\"", d.loc);
    d.loc = r.key_loc("name");
    if (auto s = unique_name(r, g.tests, "test", d.name, d.loc); !s) return s;
    std::vector<int64_t> size;
    if (auto s = r.integers("size", size, 2, 2); !s) return s;
    if (!size.empty()) {
        if (size[0] < 1 || size[1] < 1 || size[0] > 16384 || size[1] > 16384)
            return r.error(r.what() + ": size " + std::to_string(size[0]) + "x" + std::to_string(size[1]) + " is outside 1x1 .. 16384x16384",
                           r.value_loc("size"));
        d.size = std::array<int, 2>{int(size[0]), int(size[1])};
    }
    if (auto s = r.number("time", d.time); !s) return s;
    if (auto s = r.integer("frames", d.frames, 1, 100000); !s) return s;
    if (auto s = r.number("step", d.step); !s) return s;
    if (!(d.step > 0)) return r.error(r.what() + ": step must be > 0 seconds", r.value_loc("step"));
    std::vector<double> mouse;
    if (auto s = r.numbers("mouse", mouse, 4, 4); !s) return s;
    if (!mouse.empty()) d.mouse = {mouse[0], mouse[1], mouse[2], mouse[3]};
    std::vector<double> keys;
    if (auto s = r.numbers("keys", keys, 1, 256); !s) return s;
    for (double k : keys) {
        if (k != std::floor(k) || k < 0 || k > 255)
            return r.error(r.what() + ": keys are JavaScript keyCodes, integers 0..255 (65 = A, 32 = space, 37..40 = arrows)",
                           r.value_loc("keys"));
        d.held_keys.push_back(static_cast<int>(k));
    }
    auto set = r.table("set", "a table { param = value }");
    if (!set) return set.error();
    if (*set)
        for (auto&& [k, v] : **set) {
            std::string key(k.str());
            auto value = to_value(v, r, "set." + key);
            if (!value) return value.error();
            d.set[key] = *value;
            d.keys.map["set." + key] = r.loc_of(v);
        }
    auto cam = r.table("camera", "a table { target, distance, yaw, pitch }");
    if (!cam) return cam.error();
    if (*cam) {
        TableReader cr(**cam, file, r.what() + " camera");
        OrbitCamera o = g.view.orbit;  // unspecified values keep the view's
        if (auto s = parse_orbit(cr, o); !s) return s;
        d.camera = o;
    }
    if (auto s = parse_test_cameras(r, file, g, d); !s) return s;
    if (auto s = r.str("pass", d.pass); !s) return s;
    if (auto s = r.integer("mip", d.mip, 0, 15); !s) return s;  // which level/layer `pass` means
    if (auto s = r.integer("layer", d.layer, 0, 2047); !s) return s;
    if (auto s = r.str("golden", d.golden); !s) return s;
    auto tol = r.table("tolerance", "a table { rmse = number, ... }");
    if (!tol) return tol.error();
    if (*tol) {
        // The golden's tolerances (check/golden.cpp reads exactly these): an unknown key would
        // silently leave the default in force, so it is an error with a suggestion.
        TableReader tr(**tol, file, r.what() + " tolerance");
        for (auto&& [k, v] : **tol) {
            const std::string key(k.str());
            if (std::find(kGoldenTolerances.begin(), kGoldenTolerances.end(), key) == kGoldenTolerances.end()) {
                Error e = r.error(r.what() + ": unknown golden tolerance '" + key + "'", tr.key_loc(key));
                suggest(e, key, kGoldenTolerances, "golden tolerances");
                if (key == "tol") e.notes.push_back("`tol` belongs to a probe or check in checks = [...]; a golden's bound is rmse, max_abs, ...");
                return e;
            }
            if (!v.is_number()) return r.error(r.what() + ": tolerance." + key + " must be a number, not " + type_name(v), r.loc_of(v));
            double x = *v.value<double>();
            if (x < 0) return r.error(r.what() + ": tolerance." + key + " must be >= 0", r.loc_of(v));
            d.tolerance[key] = x;
        }
    }
    if (!d.tolerance.empty() && d.golden.empty())
        return r.error(r.what() + ": tolerance = { ... } bounds the golden image's difference; add golden = \"FILE.png\" (checks have their own tol)",
                       r.key_loc("tolerance"));
    // probes = [...] and checks = [...]: arrays of inline tables.
    for (const char* key : {"probes", "checks"}) {
        const toml::node* n = r.get(key);
        if (!n) continue;
        const toml::array* a = n->as_array();
        if (!a) return r.type_error(key, "an array of tables");
        for (const auto& e : *a) {
            const toml::table* ct = e.as_table();
            if (!ct) return r.error(r.what() + ": " + key + " holds tables { ... }, not " + type_name(e), r.loc_of(e));
            CheckDesc c;
            Status s = parse_check(*ct, r, c, std::string(key) == "probes" ? "probe" : nullptr);
            if (!s) return s;
            d.checks.push_back(std::move(c));
        }
    }
    if (auto s = r.strings("requires", d.requires_features); !s) return s;
    if (auto s = r.str("hint", d.hint); !s) return s;
    if (auto s = r.number("weight", d.weight); !s) return s;
    if (d.weight < 0 || d.weight > 1e6)
        return r.error(r.what() + ": weight must be between 0 and 1000000 (the case's points in `passlab grade`)",
                       r.value_loc("weight"));
    if (auto s = r.choice("visibility", d.visibility, {"visible", "hidden", "after_due_date", "after_published"}); !s)
        return s;
    return r.finish();
}

} // namespace

Status parse_test(const toml::table& t, const std::string& file, GraphDesc& g) {
    TestDesc d;
    if (auto s = parse_test_body(t, file, g, d); !s) return s;
    g.tests.push_back(std::move(d));
    return ok_status();
}

} // namespace pl::graph
