// [params], [images], [buffers], [meshes].
#include "graph/parse_parts.hpp"
#include "graph/toml_reader.hpp"

#include <algorithm>

#include <cctype>
#include <set>

namespace pl::graph {

bool is_identifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    for (char c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
    return true;
}

namespace {

const std::set<std::string> kGlslKeywords = {
    "attribute", "const", "uniform", "varying", "buffer", "shared", "layout", "centroid", "flat", "smooth",
    "break", "continue", "do", "for", "while", "switch", "case", "default", "if", "else", "in", "out", "inout",
    "float", "double", "int", "void", "bool", "true", "false", "discard", "return", "struct", "vec2", "vec3",
    "vec4", "ivec2", "ivec3", "ivec4", "bvec2", "bvec3", "bvec4", "uint", "uvec2", "uvec3", "uvec4", "mat2",
    "mat3", "mat4", "sampler2D", "precision", "highp", "mediump", "lowp", "invariant", "coherent", "volatile",
    "restrict", "readonly", "writeonly", "patch", "sample", "subroutine", "frame", "params", "main",
    // Reserved for future use by GLSL 4.50 (glslang rejects them as identifiers).
    "common", "partition", "active", "asm", "class", "union", "enum", "typedef", "template", "this",
    "resource", "goto", "inline", "noinline", "public", "static", "extern", "external", "interface",
    "long", "short", "half", "fixed", "unsigned", "superp", "input", "output", "hvec2", "hvec3",
    "hvec4", "fvec2", "fvec3", "fvec4", "filter", "sizeof", "cast", "namespace", "using",
    "precise", "texture", "dmat2", "dmat3", "dmat4"};

Status check_name(const TableReader& r, const std::string& key, const char* what) {
    if (!is_identifier(key))
        return r.error(std::string(what) + " name '" + key + "' must be an identifier (letters, digits, _)", r.key_loc(key));
    if (kGlslKeywords.count(key))
        return r.error(std::string(what) + " name '" + key + "' is a GLSL keyword or a reserved name", r.key_loc(key));
    return ok_status();
}

const std::vector<std::string> kAddress = {"repeat", "clamp", "mirror", "border"};
const std::vector<std::string> kCompare = {"never", "less", "equal", "less_equal", "greater", "not_equal",
                                           "greater_equal", "always"};

Status parse_sampler(const toml::table& t, const std::string& file, SamplerDesc& s) {
    TableReader r(t, file, "sampler");
    s.loc = r.loc();
    if (auto st = r.choice("filter", s.filter, {"linear", "nearest"}); !st) return st;
    if (auto st = r.choice("mip_filter", s.mip_filter, {"linear", "nearest"}); !st) return st;
    if (const toml::node* a = r.get("address")) {
        std::vector<std::string> modes;
        if (a->is_string()) modes = {*a->value<std::string>()};
        else if (const toml::array* arr = a->as_array()) {
            for (const auto& e : *arr)
                if (e.is_string()) modes.push_back(*e.value<std::string>());
        }
        if (modes.empty() || modes.size() > 3) return r.type_error("address", "a mode or [u, v] / [u, v, w] modes");
        for (const auto& m : modes)
            if (std::find(kAddress.begin(), kAddress.end(), m) == kAddress.end()) {
                Error e = r.error("sampler: address mode \"" + m + "\" is not one of repeat, clamp, mirror, border", r.key_loc("address"));
                std::string near = nearest_name(m, kAddress);
                if (!near.empty()) e.hint = "did you mean \"" + near + "\"?";
                return e;
            }
        for (size_t k = 0; k < 3; ++k) s.address[k] = modes[std::min(k, modes.size() - 1)];
    }
    if (auto st = r.choice("border", s.border, {"transparent_black", "opaque_black", "opaque_white"}); !st) return st;
    if (auto st = r.floats("anisotropy", s.anisotropy); !st) return st;
    if (auto st = r.choice("compare", s.compare, kCompare); !st) return st;
    if (auto st = r.floats("lod_bias", s.lod_bias); !st) return st;
    if (auto st = r.floats("min_lod", s.min_lod); !st) return st;
    if (auto st = r.floats("max_lod", s.max_lod); !st) return st;
    if (s.anisotropy < 0 || s.anisotropy > 64) return r.error("sampler: anisotropy must be 0..64", r.key_loc("anisotropy"));
    return r.finish();
}

} // namespace

Status parse_params(const toml::table& t, const std::string& file, GraphDesc& g) {
    TableReader sec(t, file, "[params]");
    for (auto&& [k, v] : t) {
        ParamDesc p;
        p.name = std::string(k.str());
        if (auto s = check_name(sec, p.name, "param"); !s) return s;
        p.loc = sec.key_loc(p.name);
        const toml::node* value = &v;
        const toml::table* pt = v.as_table();
        std::string type_name;
        std::optional<TableReader> r;
        bool color = false;
        if (pt) {
            r.emplace(*pt, file, "param '" + p.name + "'");
            value = r->get("value");
            if (!value) return r->error("param '" + p.name + "' needs a value", p.loc);
            double mn = 0, mx = 0;
            if (r->has("min")) {
                if (auto s = r->number("min", mn); !s) return s;
                p.min = mn;
            }
            if (r->has("max")) {
                if (auto s = r->number("max", mx); !s) return s;
                p.max = mx;
            }
            if (auto s = r->boolean("log", p.log); !s) return s;
            if (auto s = r->boolean("color", color); !s) return s;
            if (auto s = r->strings("options", p.options); !s) return s;
            if (auto s = r->str("doc", p.doc); !s) return s;
            if (auto s = r->choice("type", type_name, {"float", "int", "bool", "vec2", "vec3", "vec4", "color3", "color4", "enum"}); !s) return s;
            if (auto s = r->finish(); !s) return s;
        }
        // Infer the type from the value unless given.
        if (value->is_boolean()) {
            p.type = ParamType::boolean;
            p.value[0] = *value->value<bool>() ? 1 : 0;
        } else if (value->is_integer() && type_name != "float") {
            p.type = ParamType::i32;
            p.value[0] = static_cast<double>(*value->value<int64_t>());
        } else if (value->is_number()) {
            p.type = ParamType::f32;
            p.value[0] = *value->value<double>();
        } else if (value->is_string()) {
            if (p.options.empty())
                return sec.error("param '" + p.name + "': a string value needs options = [...] (an enum)", p.loc);
            std::string sv = *value->value<std::string>();
            auto it = std::find(p.options.begin(), p.options.end(), sv);
            if (it == p.options.end()) {
                Error e = sec.error("param '" + p.name + "': value \"" + sv + "\" is not one of its options", p.loc);
                std::string near = nearest_name(sv, p.options);
                if (!near.empty()) e.hint = "did you mean \"" + near + "\"?";
                return e;
            }
            p.type = ParamType::enumeration;
            p.value[0] = static_cast<double>(it - p.options.begin());
            for (const auto& o : p.options)
                if (!is_identifier(o)) return sec.error("param '" + p.name + "': option \"" + o + "\" must be an identifier", p.loc);
        } else if (const toml::array* a = value->as_array()) {
            size_t n = a->size();
            if (n < 2 || n > 4) return sec.error("param '" + p.name + "': a vector has 2 to 4 numbers", p.loc);
            for (size_t i = 0; i < n; ++i) {
                if (!(*a)[i].is_number()) return sec.error("param '" + p.name + "': a vector has 2 to 4 numbers", p.loc);
                p.value[i] = *(*a)[i].value<double>();
            }
            p.type = n == 2 ? ParamType::vec2 : n == 3 ? (color ? ParamType::color3 : ParamType::vec3)
                                                       : (color ? ParamType::color4 : ParamType::vec4);
        } else {
            return sec.error("param '" + p.name + "': value must be a number, bool, vector or enum string", p.loc);
        }
        if (type_name == "float" && p.type == ParamType::i32) p.type = ParamType::f32;
        if (type_name == "int" && p.type == ParamType::f32) {
            if (p.value[0] != static_cast<double>(static_cast<long long>(p.value[0])))
                return sec.error("param '" + p.name + "' is declared int but its value is not an integer", p.loc);
            p.type = ParamType::i32;
        }
        if (!p.options.empty() && p.type != ParamType::enumeration)
            return sec.error("param '" + p.name + "': options need a string value (one of the options)", p.loc);
        for (int c = 0; c < p.components(); ++c) {
            if (p.min && p.value[static_cast<size_t>(c)] < *p.min)
                return sec.error("param '" + p.name + "': value is below its min", p.loc);
            if (p.max && p.value[static_cast<size_t>(c)] > *p.max)
                return sec.error("param '" + p.name + "': value is above its max", p.loc);
        }
        g.params.push_back(std::move(p));
    }
    return ok_status();
}

Status parse_images(const toml::table& t, const std::string& file, GraphDesc& g) {
    TableReader sec(t, file, "[images]");
    for (auto&& [k, v] : t) {
        ImageDesc d;
        d.name = std::string(k.str());
        if (auto s = check_name(sec, d.name, "image"); !s) return s;
        d.loc = sec.key_loc(d.name);
        const toml::table* it = v.as_table();
        if (!it) return sec.error("image '" + d.name + "' must be a table { format = ..., size = ... }", d.loc);
        TableReader r(*it, file, "image '" + d.name + "'");
        std::string kind = "2d", mips;
        if (auto s = r.choice("kind", kind, {"2d", "2d-array", "3d", "cube"}); !s) return s;
        d.kind = kind == "2d-array" ? ImageKind::tex2d_array : kind == "3d" ? ImageKind::tex3d
                 : kind == "cube" ? ImageKind::cube : ImageKind::tex2d;
        if (auto s = r.str("format", d.format, &d.format_loc); !s) return s;
        if (auto s = r.size("size", d.size); !s) return s;
        if (auto s = r.integer("layers", d.layers); !s) return s;
        if (const toml::node* m = r.get("mips")) {
            if (m->is_string() && *m->value<std::string>() == "full") d.mips = 0;
            else if (m->is_integer()) d.mips = static_cast<int>(*m->value<int64_t>());
            else return r.type_error("mips", "an integer or \"full\"");
            if (m->is_integer() && (d.mips < 1 || d.mips > 16)) return r.error("mips must be 1..16 or \"full\"", r.key_loc("mips"));
        }
        if (auto s = r.integer("samples", d.samples); !s) return s;
        if (auto s = r.boolean("history", d.history); !s) return s;
        if (auto s = r.str("alias", d.alias); !s) return s;
        if (auto s = r.str("file", d.file); !s) return s;
        if (auto s = r.boolean("srgb", d.srgb); !s) return s;
        if (auto s = r.str("generator", d.generator); !s) return s;
        if (const toml::node* a = r.get("args")) {
            const toml::table* at = a->as_table();
            if (!at) return r.type_error("args", "a table of numbers or number arrays");
            for (auto&& [ak, av] : *at) {
                std::vector<double> vals;
                if (av.is_number()) vals = {*av.value<double>()};
                else if (const toml::array* arr = av.as_array())
                    for (const auto& e : *arr) {
                        if (!e.is_number()) return r.type_error("args", "a table of numbers or number arrays");
                        vals.push_back(*e.value<double>());
                    }
                else return r.type_error("args", "a table of numbers or number arrays");
                d.generator_args[std::string(ak.str())] = vals;
            }
        }
        std::vector<double> clear;
        if (auto s = r.numbers("clear", clear, 4, 4); !s) return s;
        if (!clear.empty()) d.clear = std::array<float, 4>{float(clear[0]), float(clear[1]), float(clear[2]), float(clear[3])};
        if (const toml::node* sm = r.get("sampler")) {
            if (!sm->as_table()) return r.type_error("sampler", "a table");
            if (auto s = parse_sampler(*sm->as_table(), file, d.sampler); !s) return s;
        }
        if (auto s = r.finish(); !s) return s;
        g.images.push_back(std::move(d));
    }
    return ok_status();
}

Status parse_buffers(const toml::table& t, const std::string& file, GraphDesc& g) {
    TableReader sec(t, file, "[buffers]");
    for (auto&& [k, v] : t) {
        BufferDesc d;
        d.name = std::string(k.str());
        if (auto s = check_name(sec, d.name, "buffer"); !s) return s;
        d.loc = sec.key_loc(d.name);
        const toml::table* bt = v.as_table();
        if (!bt) return sec.error("buffer '" + d.name + "' must be a table { size = ... }", d.loc);
        TableReader r(*bt, file, "buffer '" + d.name + "'");
        if (!r.has("size")) return r.error("buffer '" + d.name + "' needs a size (bytes)", d.loc);
        if (auto s = r.size("size", d.size); !s) return s;
        if (auto s = r.integer("stride", d.stride); !s) return s;
        if (r.has("clear")) {
            int c = 0;
            if (auto s = r.integer("clear", c); !s) return s;
            d.clear = static_cast<uint32_t>(c);
        }
        if (auto s = r.numbers("data", d.data, 0, 1u << 20); !s) return s;
        if (auto s = r.choice("type", d.data_type, {"float", "int", "uint"}); !s) return s;
        if (auto s = r.boolean("history", d.history); !s) return s;
        if (auto s = r.finish(); !s) return s;
        g.buffers.push_back(std::move(d));
    }
    return ok_status();
}

Status parse_meshes(const toml::table& t, const std::string& file, GraphDesc& g) {
    TableReader sec(t, file, "[meshes]");
    for (auto&& [k, v] : t) {
        MeshDesc d;
        d.name = std::string(k.str());
        if (auto s = check_name(sec, d.name, "mesh"); !s) return s;
        d.loc = sec.key_loc(d.name);
        const toml::table* mt = v.as_table();
        if (!mt) return sec.error("mesh '" + d.name + "' must be a table { generator = ... }", d.loc);
        TableReader r(*mt, file, "mesh '" + d.name + "'");
        if (auto s = r.str("generator", d.generator); !s) return s;
        if (auto s = r.str("file", d.file); !s) return s;
        if (auto s = r.integer("instances", d.instances); !s) return s;
        if (d.generator.empty() == d.file.empty())
            return r.error("mesh '" + d.name + "' needs exactly one of generator or file", d.loc);
        if (d.instances < 1 || d.instances > 1000000)
            return r.error("mesh '" + d.name + "': instances must be 1..1000000", r.key_loc("instances"));
        // Every other numeric key is a generator argument (segments, radius, ...).
        std::vector<std::string> args;
        for (auto&& [ak, av] : *mt) {
            std::string key(ak.str());
            if (key == "generator" || key == "file" || key == "instances") continue;
            if (!av.is_number()) return r.type_error(key, "a number (generator argument)");
            d.args[key] = *av.value<double>();
            args.push_back(key);
        }
        if (auto s = r.finish(args); !s) return s;
        g.meshes.push_back(std::move(d));
    }
    return ok_status();
}

} // namespace pl::graph
