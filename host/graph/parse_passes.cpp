// [[pass]] and [[test]].
#include "graph/parse_parts.hpp"
#include "graph/toml_reader.hpp"

#include <algorithm>

namespace pl::graph {

namespace {

const std::vector<std::string> kCompare = {"never", "less", "equal", "less_equal", "greater", "not_equal",
                                           "greater_equal", "always"};
const std::vector<std::string> kStencilOps = {"keep", "zero", "replace", "increment_clamp", "decrement_clamp",
                                              "invert", "increment_wrap", "decrement_wrap"};
const std::vector<std::string> kFactors = {"zero", "one", "src_color", "one_minus_src_color", "dst_color",
                                           "one_minus_dst_color", "src_alpha", "one_minus_src_alpha", "dst_alpha",
                                           "one_minus_dst_alpha", "constant_color", "src_alpha_saturate"};
const std::vector<std::string> kOps = {"add", "subtract", "reverse_subtract", "min", "max"};

Status parse_attachment(const toml::node& n, TableReader& owner, const std::string& file, AttachmentRef& a,
                        bool allow_resolve) {
    a.loc = owner.loc_of(n);
    if (n.is_string()) {
        a.image = *n.value<std::string>();
        return ok_status();
    }
    const toml::table* t = n.as_table();
    if (!t) return owner.error("an attachment is an image name or { image = ..., mip, layer }", a.loc);
    TableReader r(*t, file, "attachment");
    if (auto s = r.str("image", a.image); !s) return s;
    if (a.image.empty()) return r.error("attachment needs image = \"name\"", a.loc);
    if (auto s = r.integer("mip", a.mip); !s) return s;
    if (const toml::node* l = r.get("layer")) {
        if (l->is_integer()) a.layer = static_cast<int>(*l->value<int64_t>());
        else if (l->is_string() && *l->value<std::string>() == "all") a.layer = -1;
        else if (l->is_string() && *l->value<std::string>() == "iteration") a.layer = -2;
        else return r.type_error("layer", "an integer, \"all\" or \"iteration\"");
        if (l->is_integer() && a.layer < 0) return r.error("layer must be >= 0", r.key_loc("layer"));
    }
    if (allow_resolve)
        if (auto s = r.str("resolve", a.resolve); !s) return s;
    return r.finish();
}

Status parse_blend_one(const toml::node& n, TableReader& owner, const std::string& file, BlendDesc& b) {
    b.loc = owner.loc_of(n);
    if (n.is_string()) {
        std::string m = *n.value<std::string>();
        static const std::vector<std::string> modes = {"off", "alpha", "premultiplied", "additive", "multiply", "min", "max"};
        if (std::find(modes.begin(), modes.end(), m) == modes.end()) {
            Error e = owner.error("blend mode \"" + m + "\" is unknown", b.loc);
            std::string near = nearest_name(m, modes);
            if (!near.empty()) e.hint = "did you mean \"" + near + "\"?";
            e.notes.push_back("modes: off, alpha, premultiplied, additive, multiply, min, max, or a table of factors");
            return e;
        }
        b.enable = m != "off";
        if (m == "alpha") b.src_color = "src_alpha", b.dst_color = "one_minus_src_alpha", b.src_alpha = "one", b.dst_alpha = "one_minus_src_alpha";
        if (m == "premultiplied") b.src_color = "one", b.dst_color = "one_minus_src_alpha", b.src_alpha = "one", b.dst_alpha = "one_minus_src_alpha";
        if (m == "additive") b.src_color = b.dst_color = b.src_alpha = b.dst_alpha = "one";
        if (m == "multiply") b.src_color = "dst_color", b.dst_color = "zero", b.src_alpha = "dst_alpha", b.dst_alpha = "zero";
        if (m == "min" || m == "max") b.src_color = b.dst_color = b.src_alpha = b.dst_alpha = "one", b.color_op = b.alpha_op = m;
        return ok_status();
    }
    const toml::table* t = n.as_table();
    if (!t) return owner.error("blend is a mode name, a table of factors, or an array of those", b.loc);
    TableReader r(*t, file, "blend");
    b.enable = true;
    if (auto s = r.choice("src_color", b.src_color, kFactors); !s) return s;
    if (auto s = r.choice("dst_color", b.dst_color, kFactors); !s) return s;
    if (auto s = r.choice("color_op", b.color_op, kOps); !s) return s;
    if (auto s = r.choice("src_alpha", b.src_alpha, kFactors); !s) return s;
    if (auto s = r.choice("dst_alpha", b.dst_alpha, kFactors); !s) return s;
    if (auto s = r.choice("alpha_op", b.alpha_op, kOps); !s) return s;
    if (auto s = r.str("write_mask", b.write_mask); !s) return s;
    if (auto s = r.boolean("enable", b.enable); !s) return s;
    return r.finish();
}

Status parse_stencil_face(TableReader& r, StencilFaceDesc& f) {
    if (auto s = r.choice("fail", f.fail, kStencilOps); !s) return s;
    if (auto s = r.choice("pass", f.pass, kStencilOps); !s) return s;
    if (auto s = r.choice("depth_fail", f.depth_fail, kStencilOps); !s) return s;
    return r.choice("compare", f.compare, kCompare);
}

Status shader(TableReader& r, const char* key, ShaderRef& ref) {
    return r.str(key, ref.file, &ref.loc);
}

} // namespace

Status parse_pass(const toml::table& t, const std::string& file, GraphDesc& g) {
    PassDesc p;
    TableReader r(t, file, "[[pass]]");
    p.loc = r.loc();
    if (auto s = r.str("name", p.name); !s) return s;
    if (p.name.empty()) return r.error("[[pass]] needs a name", p.loc);
    if (!is_identifier(p.name)) return r.error("pass name '" + p.name + "' must be an identifier", r.key_loc("name"));
    p.loc = r.key_loc("name");
    std::string kind = "fullscreen";
    if (auto s = r.choice("kind", kind, {"fullscreen", "draw", "compute", "blit", "mips", "clear", "copy"}); !s) return s;
    p.kind = kind == "draw" ? PassKind::draw : kind == "compute" ? PassKind::compute : kind == "blit" ? PassKind::blit
             : kind == "mips" ? PassKind::mips : kind == "clear" ? PassKind::clear : kind == "copy" ? PassKind::copy
                              : PassKind::fullscreen;
    for (auto [key, ref] : {std::pair{"vertex", &p.vertex}, {"fragment", &p.fragment}, {"geometry", &p.geometry},
                            {"tess_control", &p.tess_control}, {"tess_eval", &p.tess_eval}, {"compute", &p.compute}})
        if (auto s = shader(r, key, *ref); !s) return s;
    auto string_map = [&](const char* key, std::map<std::string, std::string>& out, SourceLoc* where) -> Status {
        const toml::node* n = r.get(key);
        if (!n) return ok_status();
        const toml::table* mt = n->as_table();
        if (!mt) return r.type_error(key, "a table");
        if (where) *where = r.key_loc(key);
        for (auto&& [k, v] : *mt) {
            std::string val;
            if (v.is_string()) val = *v.value<std::string>();
            else if (v.is_boolean()) val = *v.value<bool>() ? "1" : "0";
            else if (v.is_integer()) val = std::to_string(*v.value<int64_t>());
            else if (v.is_floating_point()) val = std::to_string(*v.value<double>());
            else return r.type_error(key, "a table of strings or numbers");
            out[std::string(k.str())] = val;
        }
        return ok_status();
    };
    if (auto s = string_map("defines", p.defines, nullptr); !s) return s;
    if (auto s = string_map("bind", p.bind, &p.bind_loc); !s) return s;
    if (const toml::node* n = r.get("targets")) {
        const toml::array* a = n->as_array();
        if (!a) return r.type_error("targets", "an array of image names or attachment tables");
        for (const auto& e : *a) {
            AttachmentRef ar;
            if (auto s = parse_attachment(e, r, file, ar, true); !s) return s;
            p.targets.push_back(ar);
        }
    }
    if (const toml::node* n = r.get("depth")) {
        DepthDesc d;
        d.loc = r.loc_of(*n);
        if (n->is_string()) {
            d.target.image = *n->value<std::string>();
            d.target.loc = d.loc;
        } else if (const toml::table* dt = n->as_table()) {
            TableReader dr(*dt, file, "depth");
            if (auto s = dr.str("image", d.target.image); !s) return s;
            if (d.target.image.empty()) return dr.error("depth needs image = \"name\"", d.loc);
            d.target.loc = dr.key_loc("image");
            if (auto s = dr.choice("test", d.test, {"never", "less", "equal", "less_equal", "greater", "not_equal", "greater_equal", "always", "off"}); !s) return s;
            if (auto s = dr.boolean("write", d.write); !s) return s;
            if (auto s = dr.floats("bias_constant", d.bias_constant); !s) return s;
            if (auto s = dr.floats("bias_slope", d.bias_slope); !s) return s;
            if (auto s = dr.boolean("clamp", d.clamp); !s) return s;
            if (auto s = dr.integer("mip", d.target.mip); !s) return s;
            if (const toml::node* l = dr.get("layer")) {
                if (l->is_integer()) d.target.layer = static_cast<int>(*l->value<int64_t>());
                else if (l->is_string() && *l->value<std::string>() == "all") d.target.layer = -1;
                else if (l->is_string() && *l->value<std::string>() == "iteration") d.target.layer = -2;
                else return dr.type_error("layer", "an integer, \"all\" or \"iteration\"");
            }
            if (auto s = dr.finish(); !s) return s;
        } else {
            return r.type_error("depth", "an image name or a table { image, test, write }");
        }
        p.depth = d;
    }
    if (const toml::node* n = r.get("stencil")) {
        const toml::table* st = n->as_table();
        if (!st) return r.type_error("stencil", "a table");
        TableReader sr(*st, file, "stencil");
        p.stencil.enable = true;
        p.stencil.loc = sr.loc();
        int ref = 0, rm = 0xff, wm = 0xff;
        if (auto s = sr.integer("reference", ref); !s) return s;
        if (auto s = sr.integer("read_mask", rm); !s) return s;
        if (auto s = sr.integer("write_mask", wm); !s) return s;
        p.stencil.reference = static_cast<uint32_t>(ref);
        p.stencil.read_mask = static_cast<uint32_t>(rm);
        p.stencil.write_mask = static_cast<uint32_t>(wm);
        StencilFaceDesc both;
        if (auto s = parse_stencil_face(sr, both); !s) return s;
        p.stencil.front = p.stencil.back = both;
        for (auto [key, face] : {std::pair{"front", &p.stencil.front}, {"back", &p.stencil.back}}) {
            if (const toml::node* f = sr.get(key)) {
                if (!f->as_table()) return sr.type_error(key, "a table {fail, pass, depth_fail, compare}");
                TableReader fr(*f->as_table(), file, std::string("stencil.") + key);
                *face = both;
                if (auto s = parse_stencil_face(fr, *face); !s) return s;
                if (auto s = fr.finish(); !s) return s;
            }
        }
        if (auto s = sr.finish(); !s) return s;
    }
    if (const toml::node* n = r.get("blend")) {
        if (const toml::array* a = n->as_array()) {
            for (const auto& e : *a) {
                BlendDesc b;
                if (auto s = parse_blend_one(e, r, file, b); !s) return s;
                p.blend.push_back(b);
            }
        } else {
            BlendDesc b;
            if (auto s = parse_blend_one(*n, r, file, b); !s) return s;
            p.blend.push_back(b);
        }
    }
    if (const toml::node* n = r.get("clear")) {
        const toml::table* ct = n->as_table();
        if (!ct) return r.type_error("clear", "a table { color = [r,g,b,a], depth, stencil }");
        TableReader cr(*ct, file, "clear");
        std::vector<double> c;
        if (auto s = cr.numbers("color", c, 4, 4); !s) return s;
        if (!c.empty()) p.clear.color = std::array<float, 4>{float(c[0]), float(c[1]), float(c[2]), float(c[3])};
        if (cr.has("depth")) {
            float d = 1.0f;
            if (auto s = cr.floats("depth", d); !s) return s;
            p.clear.depth = d;
        }
        if (cr.has("stencil")) {
            int st = 0;
            if (auto s = cr.integer("stencil", st); !s) return s;
            p.clear.stencil = static_cast<uint32_t>(st);
        }
        if (auto s = cr.finish(); !s) return s;
    }
    if (auto s = r.str("mesh", p.mesh); !s) return s;
    if (auto s = r.integer("vertex_count", p.vertex_count); !s) return s;
    if (r.has("instances")) {
        int n = 1;
        if (auto s = r.integer("instances", n); !s) return s;
        if (n < 0 || n > 1000000) return r.error("instances must be 0..1000000", r.key_loc("instances"));
        p.instances = n;
    }
    if (const toml::node* n = r.get("indirect")) {
        if (n->is_string()) p.indirect = *n->value<std::string>();
        else if (const toml::table* it = n->as_table()) {
            TableReader ir(*it, file, "indirect");
            int off = 0;
            if (auto s = ir.str("buffer", p.indirect); !s) return s;
            if (auto s = ir.integer("offset", off); !s) return s;
            if (off < 0 || off % 4) return ir.error("indirect offset must be a non-negative multiple of 4", ir.key_loc("offset"));
            p.indirect_offset = static_cast<uint64_t>(off);
            if (auto s = ir.finish(); !s) return s;
        } else {
            return r.type_error("indirect", "a buffer name or { buffer, offset }");
        }
    }
    if (auto s = r.choice("topology", p.topology, {"triangles", "triangle_strip", "lines", "line_strip", "points", "patches", "triangles_adjacency"}); !s) return s;
    if (auto s = r.integer("patch_points", p.patch_points); !s) return s;
    if (auto s = r.choice("cull", p.cull, {"none", "back", "front"}); !s) return s;
    if (auto s = r.choice("front_face", p.front_face, {"ccw", "cw"}); !s) return s;
    if (auto s = r.choice("polygon", p.polygon, {"fill", "line", "point"}); !s) return s;
    if (auto s = r.floats("line_width", p.line_width); !s) return s;
    if (auto s = r.size("groups", p.groups); !s) return s;
    if (auto s = r.size("threads", p.threads); !s) return s;
    if (auto s = r.size("repeat", p.repeat); !s) return s;
    if (auto s = r.strings("swap", p.swap); !s) return s;
    p.swap_loc = r.key_loc("swap");
    if (p.swap.size() % 2) return r.error("swap lists pairs of images: an even number of names", p.swap_loc);
    if (auto s = r.str("src", p.src); !s) return s;
    if (auto s = r.str("dst", p.dst); !s) return s;
    if (auto s = r.str("image", p.image); !s) return s;
    if (auto s = r.choice("filter", p.filter, {"linear", "nearest"}); !s) return s;
    if (auto s = r.boolean("enabled", p.enabled); !s) return s;
    if (auto s = r.finish(); !s) return s;
    for (const auto& other : g.passes)
        if (other.name == p.name) {
            Error e = r.error("a pass named '" + p.name + "' already exists", p.loc);
            e.notes.push_back("first defined at " + other.loc.str());
            return e;
        }
    g.passes.push_back(std::move(p));
    return ok_status();
}

Status parse_test(const toml::table& t, const std::string& file, GraphDesc& g) {
    TestDesc d;
    TableReader r(t, file, "[[test]]");
    d.loc = r.loc();
    if (auto s = r.str("name", d.name); !s) return s;
    if (d.name.empty()) return r.error("[[test]] needs a name", d.loc);
    d.loc = r.key_loc("name");
    std::vector<double> size;
    if (auto s = r.numbers("size", size, 2, 2); !s) return s;
    if (!size.empty()) {
        if (size[0] < 1 || size[1] < 1 || size[0] > 16384 || size[1] > 16384)
            return r.error("test size must be between 1x1 and 16384x16384", r.key_loc("size"));
        d.size = std::array<int, 2>{int(size[0]), int(size[1])};
    }
    if (auto s = r.number("time", d.time); !s) return s;
    if (auto s = r.integer("frames", d.frames); !s) return s;
    if (d.frames < 1 || d.frames > 100000) return r.error("frames must be 1..100000", r.key_loc("frames"));
    if (auto s = r.number("step", d.step); !s) return s;
    if (const toml::node* n = r.get("set")) {
        if (!n->as_table()) return r.type_error("set", "a table { param = value }");
        for (auto&& [k, v] : *n->as_table()) d.set[std::string(k.str())] = to_value(v);
    }
    if (const toml::node* n = r.get("camera")) {
        if (!n->as_table()) return r.type_error("camera", "a table { target, distance, yaw, pitch }");
        TableReader cr(*n->as_table(), file, "test camera");
        OrbitCamera o = g.view.orbit;
        std::vector<double> target;
        if (auto s = cr.numbers("target", target, 3, 3); !s) return s;
        if (!target.empty()) o.target = {float(target[0]), float(target[1]), float(target[2])};
        if (auto s = cr.floats("distance", o.distance); !s) return s;
        if (auto s = cr.floats("yaw", o.yaw); !s) return s;
        if (auto s = cr.floats("pitch", o.pitch); !s) return s;
        if (auto s = cr.finish(); !s) return s;
        d.camera = o;
    }
    if (auto s = r.str("pass", d.pass); !s) return s;
    if (auto s = r.str("golden", d.golden); !s) return s;
    if (const toml::node* n = r.get("tolerance")) {
        if (!n->as_table()) return r.type_error("tolerance", "a table of numbers");
        for (auto&& [k, v] : *n->as_table()) {
            if (!v.is_number()) return r.type_error("tolerance", "a table of numbers");
            d.tolerance[std::string(k.str())] = *v.value<double>();
        }
    }
    auto checks = [&](const char* key, const char* kind) -> Status {
        const toml::node* n = r.get(key);
        if (!n) return ok_status();
        const toml::array* a = n->as_array();
        if (!a) return r.type_error(key, "an array of inline tables");
        for (const auto& e : *a) {
            const toml::table* ct = e.as_table();
            if (!ct) return r.type_error(key, "an array of inline tables");
            CheckDesc c;
            c.kind = kind;
            c.loc = r.loc_of(e);
            for (auto&& [k, v] : *ct) {
                if (std::string(k.str()) == "kind" && v.is_string()) c.kind = *v.value<std::string>();
                else c.args[std::string(k.str())] = to_value(v);
            }
            if (c.kind.empty()) return r.error("a check needs kind = \"...\"", c.loc);
            d.checks.push_back(std::move(c));
        }
        return ok_status();
    };
    if (auto s = checks("probes", "probe"); !s) return s;
    if (auto s = checks("checks", ""); !s) return s;
    if (auto s = r.strings("requires", d.requires_features); !s) return s;
    if (auto s = r.finish(); !s) return s;
    for (const auto& other : g.tests)
        if (other.name == d.name) return r.error("a test named '" + d.name + "' already exists", d.loc);
    g.tests.push_back(std::move(d));
    return ok_status();
}

} // namespace pl::graph
