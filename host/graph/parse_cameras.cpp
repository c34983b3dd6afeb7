// [cameras]: named views (lights, probes) that passes render from and every shader can read.
// Values are numbers or expressions; their ranges are checked where they are evaluated
// (graph/camera_values.cpp), at build time and every frame, so literals and expressions get the
// same located messages.
#include "graph/parse_parts.hpp"

#include <algorithm>

namespace pl::graph {

namespace {

Status read_float(const toml::node& n, const TableReader& r, const std::string& key, FloatExpr& out) {
    out = {};
    out.loc = r.loc_of(n);
    if (n.is_number()) {
        out.literal = {*n.value<double>()};
        return ok_status();
    }
    if (n.is_string()) {
        out.text = *n.value<std::string>();
        if (out.text.find_first_not_of(" \t") == std::string::npos) return r.error(r.what() + ": '" + key + "' is an empty expression", out.loc);
        return ok_status();
    }
    return r.error(r.what() + ": '" + key + "' must be a number or an expression string such as \"params.fov\", not " + type_name(n),
                   out.loc);
}

// [x, y, z] of numbers, [x, y, z] mixing numbers and scalar expression strings, or one string
// that evaluates to a 3-vector ("params.light_dir * 10").
Status read_vec3(const toml::node& n, const TableReader& r, const std::string& key, Vec3Expr& out) {
    out = {};
    out.loc = r.loc_of(n);
    const std::string expected = "[x, y, z] (numbers or expression strings) or an expression string such as \"params.dir * 10\"";
    if (n.is_string()) {
        FloatExpr e;
        if (auto s = read_float(n, r, key, e); !s) return s;
        out.parts = {e};
        return ok_status();
    }
    const toml::array* a = n.as_array();
    if (!a) return r.error(r.what() + ": '" + key + "' must be " + expected + ", not " + type_name(n), out.loc);
    if (a->size() != 3) return r.error(r.what() + ": '" + key + "' must have 3 components, not " + std::to_string(a->size()), out.loc);
    bool all_numbers = std::all_of(a->begin(), a->end(), [](const toml::node& e) { return e.is_number(); });
    if (all_numbers) {
        FloatExpr e;
        e.loc = out.loc;
        for (const auto& x : *a) e.literal.push_back(*x.value<double>());
        out.parts = {e};
        return ok_status();
    }
    for (const auto& x : *a) {
        FloatExpr e;
        if (!x.is_number() && !x.is_string())
            return r.error(r.what() + ": '" + key + "' must be " + expected + "; an element is " + type_name(x), r.loc_of(x));
        if (auto s = read_float(x, r, key, e); !s) return s;
        out.parts.push_back(e);
    }
    return ok_status();
}

// The keys each camera type takes besides `ortho` and `cube`.
const std::vector<std::string>& type_keys(const CameraDesc& c) {
    static const std::vector<std::string> perspective = {"eye", "target", "up", "fov", "near", "far", "aspect"};
    static const std::vector<std::string> ortho = {"eye", "target", "up", "ortho_height", "near", "far", "aspect"};
    static const std::vector<std::string> cube = {"eye", "near", "far"};
    return c.cube ? cube : c.ortho ? ortho : perspective;
}

const char* camera_type_name(const CameraDesc& c) { return c.cube ? "a cube" : c.ortho ? "an ortho" : "a perspective"; }

} // namespace

Status parse_camera(TableReader& r, CameraDesc& c) {
    if (auto s = r.boolean("ortho", c.ortho); !s) return s;
    if (auto s = r.boolean("cube", c.cube); !s) return s;
    for (auto [key, v] : {std::pair{"eye", &c.eye}, {"target", &c.target}, {"up", &c.up}})
        if (const toml::node* n = r.get(key))
            if (auto s = read_vec3(*n, r, key, *v); !s) return s;
    for (auto [key, f] : {std::pair{"fov", &c.fov}, {"near", &c.near}, {"far", &c.far}, {"aspect", &c.aspect},
                          {"ortho_height", &c.ortho_height}})
        if (const toml::node* n = r.get(key))
            if (auto s = read_float(*n, r, key, *f); !s) return s;
    if (auto s = r.finish(); !s) return s;
    // Keys of another camera type are errors, not ignored: `fov` on an ortho camera is a
    // misunderstanding to point out.
    if (c.ortho && c.cube) return r.error(r.what() + ": a camera is ortho or cube, not both", c.keys.at("cube", r.loc()));
    const auto& allowed = type_keys(c);
    for (const auto& [key, loc] : c.keys.map)
        if (key != "ortho" && key != "cube" && std::find(allowed.begin(), allowed.end(), key) == allowed.end()) {
            Error e = r.error(r.what() + ": '" + key + "' does not apply to " + camera_type_name(c) + " camera", loc);
            std::string list;
            for (const auto& k : allowed) list += (list.empty() ? "" : ", ") + k;
            e.notes.push_back(std::string(camera_type_name(c)) + " camera takes " + list + (c.cube ? " (its six faces look along the axes)" : ""));
            return e;
        }
    if (c.eye.parts.empty()) return r.error(r.what() + " needs eye = [x, y, z]", r.loc());
    if (!c.cube && c.target.parts.empty()) return r.error(r.what() + " needs target = [x, y, z]", r.loc());
    return ok_status();
}

Status parse_cameras(const toml::table& t, const std::string& file, GraphDesc& g) {
    TableReader sec(t, file, "[cameras]");
    int faces = 0;
    for (auto&& [k, v] : t) {
        CameraDesc c;
        c.name = std::string(k.str());
        if (auto s = check_name(sec, c.name, "camera"); !s) return s;
        c.loc = sec.key_loc(c.name);
        const toml::table* ct = v.as_table();
        if (!ct) return sec.error("camera '" + c.name + "' must be a table { eye = [...], target = [...], ... }, not " + type_name(v), sec.loc_of(v));
        TableReader r(*ct, file, "camera '" + c.name + "'", &c.keys);
        if (auto s = parse_camera(r, c); !s) return s;
        // The cameras block holds one 416-byte entry per camera and cube face; 16 KiB is the
        // smallest maxUniformBufferRange a Vulkan device may have, so a graph that fits runs on all.
        faces += c.faces();
        if (faces > kMaxCameraEntries)
            return sec.error("camera '" + c.name + "': the graph's cameras need " + std::to_string(faces) +
                                 " entries (a cube camera counts 6); at most " + std::to_string(kMaxCameraEntries) +
                                 " fit the 16 KiB uniform block every device supports",
                             c.loc);
        g.cameras.push_back(std::move(c));
    }
    return ok_status();
}

} // namespace pl::graph
