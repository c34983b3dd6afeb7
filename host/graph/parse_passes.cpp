// [[pass]]: one table per pass. Values are only read and typed here; whether the names they hold
// exist, whether the kind has what it needs, and whether sizes evaluate is validate.cpp's job
// (it sees the whole graph).
#include "graph/parse_parts.hpp"

#include <algorithm>
#include <charconv>
#include <cmath>

namespace pl::graph {

namespace {

// In the order of PassKind.
const std::vector<std::string> kKinds = {"fullscreen", "draw", "compute", "blit", "mips", "clear", "copy"};
const std::vector<std::string> kStencilOps = {"keep", "zero", "replace", "increment_clamp", "decrement_clamp",
                                              "invert", "increment_wrap", "decrement_wrap"};
const std::vector<std::string> kFactors = {"zero", "one", "src_color", "one_minus_src_color", "dst_color",
                                           "one_minus_dst_color", "src_alpha", "one_minus_src_alpha", "dst_alpha",
                                           "one_minus_dst_alpha", "constant_color", "src_alpha_saturate"};
const std::vector<std::string> kOps = {"add", "subtract", "reverse_subtract", "min", "max"};
const std::vector<std::string> kBlendModes = {"off", "alpha", "premultiplied", "additive", "multiply", "min", "max"};

// layer = integer >= 0 | "all" (-1) | "iteration" (-2) | an expression over `iteration`
// (into `expr`, when given).
Status parse_layer(TableReader& r, int& layer, SizeExpr* expr = nullptr) {
    const toml::node* l = r.get("layer");
    if (!l) return ok_status();
    if (expr && l->is_string() && *l->value<std::string>() != "all" && *l->value<std::string>() != "iteration") {
        // An expression uses an operator or a function ("iteration / 6", "min(iteration, 3)");
        // a lone word such as "every" is a misspelt keyword, refused here with the choices.
        const std::string v = *l->value<std::string>();
        if (v.find_first_of("+-*/%()0123456789") == std::string::npos)
            return r.error(r.what() + ": layer \"" + v + "\" is not \"all\", \"iteration\" or an expression such as \"iteration / 6\"",
                           r.value_loc("layer"));
        return r.size("layer", *expr);
    }
    if (l->is_integer()) {
        int64_t v = *l->value<int64_t>();
        if (v < 0 || v > 2047) return r.error(r.what() + ": layer must be 0..2047, \"all\" or \"iteration\"", r.loc_of(*l));
        layer = static_cast<int>(v);
    } else if (l->is_string() && *l->value<std::string>() == "all") {
        layer = -1;
    } else if (l->is_string() && *l->value<std::string>() == "iteration") {
        layer = -2;
    } else {
        return r.type_error("layer", "an integer, \"all\" or \"iteration\"");
    }
    return ok_status();
}

// mip = integer 0..15 | an expression over `iteration` ("iteration + 1").
Status parse_mip(TableReader& r, int& mip, SizeExpr& expr) {
    const toml::node* m = r.get("mip");
    if (m && m->is_string()) return r.size("mip", expr);
    return r.integer("mip", mip, 0, 15);
}

Status parse_attachment(const toml::node& n, TableReader& owner, AttachmentRef& a) {
    a.loc = owner.loc_of(n);
    if (n.is_string()) {
        a.image = *n.value<std::string>();
        if (a.image.empty()) return owner.error(owner.what() + ": a target must name an image", a.loc);
        return ok_status();
    }
    const toml::table* t = n.as_table();
    if (!t) return owner.error(owner.what() + ": a target is an image name or { image, mip, layer, resolve }, not " + type_name(n), a.loc);
    TableReader r(*t, owner.file(), owner.what() + " target");
    if (auto s = r.str("image", a.image); !s) return s;
    if (a.image.empty()) return r.error(r.what() + " needs image = \"name\"", a.loc);
    a.loc = r.value_loc("image");
    if (auto s = parse_mip(r, a.mip, a.mip_expr); !s) return s;
    if (auto s = parse_layer(r, a.layer, &a.layer_expr); !s) return s;
    if (auto s = r.str("resolve", a.resolve, &a.resolve_loc); !s) return s;
    return r.finish();
}

// bind = { name = { image = "hiz", mip = "iteration", layer = 2 } }: one level/layer of an image.
Status parse_view(const toml::table& t, TableReader& owner, ViewRef& v) {
    v.loc = owner.loc_of(t);
    TableReader r(t, owner.file(), owner.what() + " bind view");
    if (auto s = r.str("image", v.image); !s) return s;
    if (v.image.empty()) return r.error(r.what() + " needs image = \"name\" (and mip and/or layer)", v.loc);
    if (auto s = r.size("mip", v.mip); !s) return s;
    if (auto s = r.size("layer", v.layer); !s) return s;
    for (const SizeExpr* e : {&v.mip, &v.layer})
        if (e->literal.size() > 1) return r.error(r.what() + ": mip and layer are one number (or an expression), not a vector", e->loc);
    if (auto s = r.finish(); !s) return s;  // a misspelt key first: it is why nothing is selected
    if (v.mip.empty() && v.layer.empty()) return r.error(r.what() + " selects nothing: give mip and/or layer, or bind the name as a string", v.loc);
    return ok_status();
}

Status parse_blend_one(const toml::node& n, TableReader& owner, BlendDesc& b) {
    b.loc = owner.loc_of(n);
    if (n.is_string()) {
        std::string m = *n.value<std::string>();
        if (!std::count(kBlendModes.begin(), kBlendModes.end(), m)) {
            Error e = owner.error(owner.what() + ": blend mode \"" + m + "\" is unknown", b.loc);
            suggest(e, m, kBlendModes, "modes", {}, '"');
            e.notes.push_back("or a table { src_color, dst_color, color_op, src_alpha, dst_alpha, alpha_op, write_mask }");
            return e;
        }
        // The named modes, as factors (result = src * src_factor OP dst * dst_factor).
        b.enable = m != "off";
        if (m == "alpha") b.src_color = "src_alpha", b.dst_color = "one_minus_src_alpha", b.src_alpha = "one", b.dst_alpha = "one_minus_src_alpha";
        if (m == "premultiplied") b.src_color = "one", b.dst_color = "one_minus_src_alpha", b.src_alpha = "one", b.dst_alpha = "one_minus_src_alpha";
        if (m == "additive") b.src_color = b.dst_color = b.src_alpha = b.dst_alpha = "one";
        if (m == "multiply") b.src_color = "dst_color", b.dst_color = "zero", b.src_alpha = "dst_alpha", b.dst_alpha = "zero";
        // Vulkan ignores the factors of min/max; "one" keeps the description honest.
        if (m == "min" || m == "max") b.src_color = b.dst_color = b.src_alpha = b.dst_alpha = "one", b.color_op = b.alpha_op = m;
        return ok_status();
    }
    const toml::table* t = n.as_table();
    if (!t) return owner.error(owner.what() + ": blend is a mode name, a table of factors, or an array of those, not " + type_name(n), b.loc);
    TableReader r(*t, owner.file(), owner.what() + " blend");
    b.enable = true;
    if (auto s = r.choice("src_color", b.src_color, kFactors); !s) return s;
    if (auto s = r.choice("dst_color", b.dst_color, kFactors); !s) return s;
    if (auto s = r.choice("color_op", b.color_op, kOps); !s) return s;
    if (auto s = r.choice("src_alpha", b.src_alpha, kFactors); !s) return s;
    if (auto s = r.choice("dst_alpha", b.dst_alpha, kFactors); !s) return s;
    if (auto s = r.choice("alpha_op", b.alpha_op, kOps); !s) return s;
    if (auto s = r.str("write_mask", b.write_mask); !s) return s;
    if (auto s = r.boolean("enable", b.enable); !s) return s;
    // write_mask: the channels written, each of r g b a at most once ("" writes nothing).
    std::string seen;
    for (char c : b.write_mask)
        if (std::string("rgba").find(c) == std::string::npos || seen.find(c) != std::string::npos)
            return r.error(r.what() + ": write_mask \"" + b.write_mask + "\" must be made of r, g, b, a (each once)", r.value_loc("write_mask"));
        else
            seen += c;
    return r.finish();
}

Status parse_stencil_face(TableReader& r, StencilFaceDesc& f) {
    if (auto s = r.choice("fail", f.fail, kStencilOps); !s) return s;
    if (auto s = r.choice("pass", f.pass, kStencilOps); !s) return s;
    if (auto s = r.choice("depth_fail", f.depth_fail, kStencilOps); !s) return s;
    return r.choice("compare", f.compare, compare_ops());
}

// A define's value as GLSL text: strings verbatim, integers in decimal, floats in the shortest
// form that reads back exactly and still looks like a float ("0.5", "1.0", "1e-07"), bools 1/0
// (so that `#if NAME` works).
Result<std::string> define_text(const toml::node& v, const TableReader& r, const std::string& key) {
    if (v.is_string()) {
        // One line of GLSL: a newline would end the #define inside the preamble, where the
        // error would be reported far from here.
        std::string t = *v.value<std::string>();
        if (t.empty()) return r.error(r.what() + ": defines." + key + " is empty (use true/false or 1/0 for a flag)", r.loc_of(v));
        for (char c : t)
            if (static_cast<unsigned char>(c) < 0x20 && c != '\t')
                return r.error(r.what() + ": defines." + key + " must be one line of GLSL (no newline or control character)", r.loc_of(v));
        if (t.back() == '\\') return r.error(r.what() + ": defines." + key + " must not end in a backslash (a line continuation)", r.loc_of(v));
        return t;
    }
    if (v.is_boolean()) return std::string(*v.value<bool>() ? "1" : "0");
    if (v.is_integer()) return std::to_string(*v.value<int64_t>());
    if (v.is_floating_point()) {
        double d = *v.value<double>();
        if (!std::isfinite(d)) return r.error(r.what() + ": defines." + key + " must be finite (GLSL has no nan or inf literal)", r.loc_of(v));
        char buf[64];
        auto res = std::to_chars(buf, buf + sizeof buf, d);
        std::string s(buf, res.ptr);
        if (s.find_first_of(".eEn") == std::string::npos) s += ".0";  // n: nan/inf
        return s;
    }
    return r.error(r.what() + ": defines." + key + " must be a string, number or bool, not " + type_name(v), r.loc_of(v));
}

Status parse_depth(const toml::node& n, TableReader& r, DepthDesc& d, KeyLocs& locs) {
    d.loc = r.loc_of(n);
    if (n.is_string()) {
        d.target.image = *n.value<std::string>();
        d.target.loc = d.loc;
        locs.map["depth.image"] = d.loc;
        if (d.target.image.empty()) return r.error(r.what() + ": depth must name an image", d.loc);
        return ok_status();
    }
    const toml::table* dt = n.as_table();
    if (!dt) return r.type_error("depth", "an image name or a table { image, test, write, ... }");
    TableReader dr(*dt, r.file(), r.what() + " depth", &locs, "depth.");
    if (auto s = dr.str("image", d.target.image); !s) return s;
    if (d.target.image.empty()) return dr.error(dr.what() + " needs image = \"name\"", d.loc);
    d.target.loc = dr.value_loc("image");
    std::vector<std::string> tests = compare_ops();
    tests.push_back("off");
    if (auto s = dr.choice("test", d.test, tests); !s) return s;
    if (auto s = dr.boolean("write", d.write); !s) return s;
    if (auto s = dr.floats("bias_constant", d.bias_constant); !s) return s;
    if (auto s = dr.floats("bias_slope", d.bias_slope); !s) return s;
    if (auto s = dr.boolean("clamp", d.clamp); !s) return s;
    if (auto s = parse_mip(dr, d.target.mip, d.target.mip_expr); !s) return s;
    if (auto s = parse_layer(dr, d.target.layer, &d.target.layer_expr); !s) return s;
    return dr.finish();
}

Status parse_stencil(const toml::table& st, TableReader& r, StencilDesc& out, KeyLocs& locs) {
    TableReader sr(st, r.file(), r.what() + " stencil", &locs, "stencil.");
    out.enable = true;  // presence enables the stencil test
    out.loc = sr.loc();
    if (auto s = sr.uinteger("reference", out.reference, 255); !s) return s;
    if (auto s = sr.uinteger("read_mask", out.read_mask, 255); !s) return s;
    if (auto s = sr.uinteger("write_mask", out.write_mask, 255); !s) return s;
    // Flat fail/pass/depth_fail/compare apply to both faces; front/back override per face.
    StencilFaceDesc both;
    if (auto s = parse_stencil_face(sr, both); !s) return s;
    out.front = out.back = both;
    for (auto [key, face] : {std::pair{"front", &out.front}, {"back", &out.back}}) {
        auto f = sr.table(key, "a table { fail, pass, depth_fail, compare }");
        if (!f) return f.error();
        if (!*f) continue;
        TableReader fr(**f, r.file(), sr.what() + "." + key);
        if (auto s = parse_stencil_face(fr, *face); !s) return s;
        if (auto s = fr.finish(); !s) return s;
    }
    return sr.finish();
}

Status parse_clear(const toml::table& ct, TableReader& r, ClearDesc& c, KeyLocs& locs) {
    TableReader cr(ct, r.file(), r.what() + " clear", &locs, "clear.");
    std::vector<double> col;
    if (auto s = cr.numbers("color", col, 4, 4); !s) return s;
    if (!col.empty()) c.color = std::array<double, 4>{col[0], col[1], col[2], col[3]};
    if (cr.has("depth")) {
        float d = 1.0f;
        if (auto s = cr.floats("depth", d); !s) return s;
        if (d < 0 || d > 1) return cr.error(cr.what() + ": depth must be between 0 and 1", cr.value_loc("depth"));
        c.depth = d;
    }
    if (cr.has("stencil")) {
        uint32_t st = 0;
        if (auto s = cr.uinteger("stencil", st, 255); !s) return s;
        c.stencil = st;
    }
    return cr.finish();
}

} // namespace

namespace {

Status parse_pass_body(const toml::table& t, const std::string& file, GraphDesc& g, PassDesc& p) {
    const std::string what = "[[pass]]";  // messages add [pass 'name'] from Error::pass
    TableReader r(t, file, what, &p.keys);
    p.loc = r.loc();
    if (auto s = r.str("name", p.name); !s) return s;
    if (p.name.empty()) return r.error("[[pass]] needs name = \"...\"", p.loc);
    if (!is_identifier(p.name)) return r.error("pass name '" + p.name + "' must be an identifier (letters, digits, _)", r.value_loc("name"));
    p.loc = r.key_loc("name");  // the pass is where its name is written
    if (auto s = unique_name(r, g.passes, "pass", p.name, p.loc); !s) {
        Error e = s.error();
        e.pass = p.name;
        return e;
    }
    std::string kind = "fullscreen";
    if (auto s = r.choice("kind", kind, kKinds); !s) return s;
    p.kind = static_cast<PassKind>(std::find(kKinds.begin(), kKinds.end(), kind) - kKinds.begin());
    for (auto [key, ref] : {std::pair{"vertex", &p.vertex}, {"fragment", &p.fragment}, {"geometry", &p.geometry},
                            {"tess_control", &p.tess_control}, {"tess_eval", &p.tess_eval}, {"compute", &p.compute}}) {
        if (auto s = r.str(key, ref->file, &ref->loc); !s) return s;
        if (r.has(key) && ref->file.empty()) return r.error(what + ": " + key + " must name a shader file", r.value_loc(key));
    }
    if (auto dt = r.table("defines", "a table { NAME = value }"); !dt) return dt.error();
    else if (*dt)
        for (auto&& [k, v] : **dt) {
            std::string key(k.str());
            if (!is_identifier(key)) return r.error(what + ": define name '" + key + "' must be an identifier", r.loc_of(v));
            auto text = define_text(v, r, key);
            if (!text) return text.error();
            p.defines[key] = *text;
            p.keys.map["defines." + key] = r.loc_of(v);
        }
    if (auto bt = r.table("bind", "a table { shader_name = \"resource\" }"); !bt) return bt.error();
    else if (*bt) {
        p.bind_loc = r.value_loc("bind");
        for (auto&& [k, v] : **bt) {
            std::string key(k.str());
            if (const toml::table* vt = v.as_table()) {
                ViewRef view;
                if (auto s = parse_view(*vt, r, view); !s) return s;
                p.bind[key] = view.image;
                p.bind_views[key] = view;
                p.keys.map["bind." + key] = r.loc_of(v);
                continue;
            }
            if (!v.is_string())
                return r.error(what + ": bind." + key + " must be a resource name (a string) or { image, mip, layer }, not " + type_name(v), r.loc_of(v));
            p.bind[key] = *v.value<std::string>();
            p.keys.map["bind." + key] = r.loc_of(v);
        }
    }
    if (const toml::node* n = r.get("targets")) {
        const toml::array* a = n->as_array();
        if (!a) return r.type_error("targets", "an array of image names or { image, mip, layer, resolve } tables");
        for (const auto& e : *a) {
            AttachmentRef ar;
            if (auto s = parse_attachment(e, r, ar); !s) return s;
            p.targets.push_back(ar);
        }
    }
    if (const toml::node* n = r.get("depth")) {
        DepthDesc d;
        if (auto s = parse_depth(*n, r, d, p.keys); !s) return s;
        p.depth = d;
    }
    if (auto st = r.table("stencil", "a table { reference, read_mask, write_mask, fail, pass, depth_fail, compare, front, back }"); !st)
        return st.error();
    else if (*st) {
        if (auto s = parse_stencil(**st, r, p.stencil, p.keys); !s) return s;
    }
    if (const toml::node* n = r.get("blend")) {
        if (const toml::array* a = n->as_array()) {
            if (a->empty()) return r.error(what + ": blend = [] is empty; give one mode per target", r.loc_of(*n));
            for (const auto& e : *a) {
                BlendDesc b;
                if (auto s = parse_blend_one(e, r, b); !s) return s;
                p.blend.push_back(b);
            }
        } else {
            BlendDesc b;
            if (auto s = parse_blend_one(*n, r, b); !s) return s;
            p.blend.push_back(b);
        }
    }
    if (auto ct = r.table("clear", "a table { color = [r, g, b, a], depth, stencil }"); !ct) return ct.error();
    else if (*ct) {
        if (auto s = parse_clear(**ct, r, p.clear, p.keys); !s) return s;
    }
    if (auto s = r.str("mesh", p.mesh); !s) return s;
    if (auto s = r.integer("vertex_count", p.vertex_count, 0, 1 << 28); !s) return s;
    if (r.has("instances")) {
        int n = 1;
        if (auto s = r.integer("instances", n, 0, 1000000); !s) return s;
        p.instances = n;
    }
    if (const toml::node* n = r.get("indirect")) {
        if (n->is_string()) {
            p.indirect = *n->value<std::string>();
        } else if (const toml::table* it = n->as_table()) {
            TableReader ir(*it, file, what + " indirect", &p.keys, "indirect.");
            int off = 0;
            if (auto s = ir.str("buffer", p.indirect); !s) return s;
            if (auto s = ir.integer("offset", off, 0, INT32_MAX); !s) return s;
            if (off % 4) return ir.error(ir.what() + ": offset must be a multiple of 4", ir.value_loc("offset"));
            p.indirect_offset = static_cast<uint64_t>(off);
            if (auto s = ir.finish(); !s) return s;
            if (ir.has("buffer")) p.keys.map["indirect"] = ir.value_loc("buffer");
        } else {
            return r.type_error("indirect", "a buffer name or { buffer, offset }");
        }
        if (p.indirect.empty()) return r.error(what + ": indirect must name a buffer", r.value_loc("indirect"));
    }
    if (auto s = r.choice("topology", p.topology, {"triangles", "triangle_strip", "lines", "line_strip", "points", "patches", "triangles_adjacency"}); !s) return s;
    if (auto s = r.integer("patch_points", p.patch_points, 1, 32); !s) return s;
    if (auto s = r.choice("cull", p.cull, {"none", "back", "front"}); !s) return s;
    if (auto s = r.choice("front_face", p.front_face, {"ccw", "cw"}); !s) return s;
    if (auto s = r.choice("polygon", p.polygon, {"fill", "line", "point"}); !s) return s;
    if (auto s = r.floats("line_width", p.line_width); !s) return s;
    if (!(p.line_width > 0)) return r.error(what + ": line_width must be > 0", r.value_loc("line_width"));
    if (auto s = r.size("groups", p.groups); !s) return s;
    if (auto s = r.size("threads", p.threads); !s) return s;
    if (auto s = r.size("repeat", p.repeat); !s) return s;
    if (p.repeat.literal.size() > 1) return r.error(what + ": repeat is a count (an integer or an expression), not a vector", p.repeat.loc);
    if (auto s = r.strings("swap", p.swap); !s) return s;
    p.swap_loc = r.value_loc("swap");
    if (p.swap.size() % 2) return r.error(what + ": swap lists pairs of images: an even number of names", p.swap_loc);
    if (auto s = r.str("src", p.src); !s) return s;
    if (auto s = r.str("dst", p.dst); !s) return s;
    if (auto s = r.str("image", p.image); !s) return s;
    if (auto s = r.choice("filter", p.filter, {"linear", "nearest"}); !s) return s;
    if (r.has("enabled")) {
        // true/false, or a string expression over params re-evaluated every frame (nonzero = on).
        const toml::node* n = r.get("enabled");
        if (n->is_string()) {
            if (auto s = r.size("enabled", p.enabled_when); !s) return s;
            if (p.enabled_when.text.empty())
                return r.error(what + ": enabled is true, false or an expression such as \"params.verify\"", r.value_loc("enabled"));
        } else if (auto s = r.boolean("enabled", p.enabled); !s) {
            return r.error(what + ": enabled is true, false or an expression such as \"params.verify\"", r.value_loc("enabled"));
        }
    }
    if (auto s = r.boolean("bake", p.bake); !s) return s;
    if (auto s = r.str("camera", p.camera); !s) return s;
    if (r.has("camera") && p.camera.empty()) return r.error(what + ": camera must name a camera of [cameras]", r.value_loc("camera"));
    return r.finish();
}

} // namespace

Status parse_pass(const toml::table& t, const std::string& file, GraphDesc& g) {
    PassDesc p;
    if (auto s = parse_pass_body(t, file, g, p); !s) {
        if (s.error().pass.empty()) s.error().pass = p.name;
        return s;
    }
    g.passes.push_back(std::move(p));
    return ok_status();
}

} // namespace pl::graph
