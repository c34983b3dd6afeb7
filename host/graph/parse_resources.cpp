// [images], [buffers], [meshes]: the resources passes read and write, by name.
#include "graph/parse_parts.hpp"

#include "vk/formats.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <filesystem>

namespace pl::graph {

namespace {

// The generators and their arguments are implemented in image/procedural.cpp and
// scene/generators.cpp (image::generator_names, scene::generator_names), which the graph module
// cannot link; the lists are repeated here so that a typo is reported at its TOML line with a
// suggestion instead of when the resource is created. Adding a generator means adding it here.
const std::vector<std::string> kImageGenerators = {"checker", "uv-grid", "value-noise", "gradient-noise", "constant"};
const std::vector<std::string> kImageGeneratorArgs = {"cells", "color_a", "color_b", "frequency", "octaves", "seed", "value"};
const std::vector<std::string> kMeshGenerators = {"plane", "cube", "sphere", "torus", "teapot"};
const std::vector<std::string> kMeshArgs = {"size", "segments", "rings", "radius", "tube", "subdivisions"};

// Host-built scene buffers (scene/scene_buffer.hpp).
const std::vector<std::string> kBufferGenerators = {"bvh", "triangles"};

const std::vector<std::string> kAddress = {"repeat", "clamp", "mirror", "border"};

bool contains(const std::vector<std::string>& v, const std::string& s) { return std::find(v.begin(), v.end(), s) != v.end(); }

// Errors about one resource name it (the [resource 'x'] of the message).
Status named(Status s, const std::string& resource) {
    if (!s && s.error().resource.empty()) s.error().resource = resource;
    return s;
}

Status parse_sampler(const toml::table& t, const std::string& file, const std::string& image, SamplerDesc& s, KeyLocs& locs) {
    TableReader r(t, file, "image '" + image + "' sampler", &locs, "sampler.");
    s.loc = r.loc();
    if (auto st = r.choice("filter", s.filter, {"linear", "nearest"}); !st) return st;
    if (auto st = r.choice("mip_filter", s.mip_filter, {"linear", "nearest"}); !st) return st;
    if (const toml::node* a = r.get("address")) {
        // One mode for every axis, or [u, v] / [u, v, w] (a missing w repeats v).
        std::vector<std::pair<std::string, SourceLoc>> modes;
        if (a->is_string()) modes = {{*a->value<std::string>(), r.loc_of(*a)}};
        else if (const toml::array* arr = a->as_array()) {
            for (const auto& e : *arr) {
                if (!e.is_string()) return r.type_error("address", "a mode or an array of 2 or 3 modes");
                modes.push_back({*e.value<std::string>(), r.loc_of(e)});
            }
            if (modes.size() < 2 || modes.size() > 3) return r.type_error("address", "a mode or an array of 2 or 3 modes");
        } else {
            return r.type_error("address", "a mode or an array of 2 or 3 modes");
        }
        for (const auto& [m, where] : modes)
            if (!contains(kAddress, m)) {
                Error e = r.error(r.what() + ": address mode \"" + m + "\" is unknown", where);
                suggest(e, m, kAddress, "modes", {}, '"');
                return e;
            }
        for (size_t k = 0; k < 3; ++k) s.address[k] = modes[std::min(k, modes.size() - 1)].first;
    }
    if (auto st = r.choice("border", s.border, {"transparent_black", "opaque_black", "opaque_white"}); !st) return st;
    if (auto st = r.floats("anisotropy", s.anisotropy); !st) return st;
    if (auto st = r.choice("compare", s.compare, compare_ops()); !st) return st;
    if (auto st = r.floats("lod_bias", s.lod_bias); !st) return st;
    if (auto st = r.floats("min_lod", s.min_lod); !st) return st;
    if (auto st = r.floats("max_lod", s.max_lod); !st) return st;
    if (s.anisotropy < 0 || s.anisotropy > 64) return r.error(r.what() + ": anisotropy must be 0 (off) to 64", r.value_loc("anisotropy"));
    if (s.min_lod < 0 || s.max_lod < s.min_lod) return r.error(r.what() + ": needs 0 <= min_lod <= max_lod", r.value_loc(r.has("max_lod") ? "max_lod" : "min_lod"));
    return r.finish();
}

Status parse_generator_args(TableReader& r, const std::string& image, ImageDesc& d) {
    auto at = r.table("args", "a table { name = number or [numbers] }");
    if (!at) return at.error();
    if (!*at) return ok_status();
    for (auto&& [ak, av] : **at) {
        std::string key(ak.str());
        SourceLoc where = r.loc_of(av);
        if (!contains(kImageGeneratorArgs, key)) {
            Error e = r.error("image '" + image + "': unknown generator argument '" + key + "'", where);
            suggest(e, key, kImageGeneratorArgs, "arguments");
            return e;
        }
        std::vector<double> vals;
        if (av.is_number()) vals = {*av.value<double>()};
        else if (const toml::array* arr = av.as_array()) {
            for (const auto& e : *arr) {
                if (!e.is_number()) return r.error("image '" + image + "': args." + key + " must be a number or an array of numbers", where);
                vals.push_back(*e.value<double>());
            }
        }
        if (vals.empty() || vals.size() > 4) return r.error("image '" + image + "': args." + key + " must be a number or 1 to 4 numbers", where);
        d.generator_args[key] = vals;
        d.keys.map["args." + key] = where;
    }
    return ok_status();
}

Status parse_image(const toml::table& it, const std::string& file, ImageDesc& d) {
    TableReader r(it, file, "image '" + d.name + "'", &d.keys);
    auto err = [&](const std::string& msg, const std::string& key) {
        Error e = r.error("image '" + d.name + "': " + msg, r.value_loc(key));
        e.resource = d.name;
        return e;
    };
    if (r.has("alias")) {
        // An alias is another view of an existing image: same memory, same size and format,
        // its own sampler. Anything else written on it would be silently ignored: refuse it.
        if (auto s = r.str("alias", d.alias); !s) return s;
        if (d.alias.empty()) return err("alias must name an image", "alias");
        if (auto sm = r.table("sampler"); !sm) return sm.error();
        else if (*sm) {
            if (auto s = parse_sampler(**sm, file, d.name, d.sampler, d.keys); !s) return s;
        }
        for (auto&& [k, v] : it) {
            std::string key(k.str());
            if (key != "alias" && key != "sampler")
                return err("'" + key + "' cannot be set on an alias; it shares '" + d.alias + "' (only sampler may differ)", key);
        }
        return ok_status();
    }
    std::string kind = "2d";
    if (auto s = r.choice("kind", kind, {"2d", "2d-array", "3d", "cube"}); !s) return s;
    d.kind = kind == "2d-array" ? ImageKind::tex2d_array : kind == "3d" ? ImageKind::tex3d
             : kind == "cube"   ? ImageKind::cube        : ImageKind::tex2d;
    if (auto s = r.str("format", d.format, &d.format_loc); !s) return s;
    if (r.has("format") && !vk::find_format(d.format)) {
        Error e = err("unknown format '" + d.format + "'", "format");
        suggest(e, d.format, vk::format_names(), "formats");
        return e;
    }
    if (auto s = r.size("size", d.size); !s) return s;
    if (auto s = r.integer("layers", d.layers, 1, 2048); !s) return s;
    if (r.has("layers") && d.kind != ImageKind::tex2d_array)
        return err("layers applies to kind = \"2d-array\" (a cube always has 6)", "layers");
    if (const toml::node* m = r.get("mips")) {
        if (m->is_string() && *m->value<std::string>() == "full") d.mips = 0;
        else if (m->is_integer()) {
            int64_t v = *m->value<int64_t>();
            if (v < 1 || v > 16) return err("mips must be 1..16 or \"full\", not " + std::to_string(v), "mips");
            d.mips = static_cast<int>(v);
        } else {
            return r.type_error("mips", "an integer or \"full\"");
        }
    }
    if (auto s = r.integer("samples", d.samples); !s) return s;
    if (d.samples != 1 && d.samples != 2 && d.samples != 4 && d.samples != 8)
        return err("samples must be 1, 2, 4 or 8, not " + std::to_string(d.samples), "samples");
    if (auto s = r.boolean("history", d.history); !s) return s;
    if (auto s = r.str("file", d.file); !s) return s;
    if (auto s = r.boolean("srgb", d.srgb); !s) return s;
    if (auto s = r.boolean("flip_y", d.flip_y); !s) return s;
    if (auto s = r.choice("generator", d.generator, kImageGenerators); !s) return s;
    if (auto s = parse_generator_args(r, d.name, d); !s) return s;
    std::vector<double> clear;
    if (auto s = r.numbers("clear", clear, 4, 4); !s) return s;
    if (!clear.empty()) d.clear = std::array<double, 4>{clear[0], clear[1], clear[2], clear[3]};
    if (auto sm = r.table("sampler"); !sm) return sm.error();
    else if (*sm) {
        if (auto s = parse_sampler(**sm, file, d.name, d.sampler, d.keys); !s) return s;
    }
    if (auto s = r.finish(); !s) return s;

    if (r.has("file") && d.file.empty()) return err("file must name an image file", "file");
    if (!d.file.empty() && !d.generator.empty()) return err("has both file and generator; choose one", "generator");
    if (!d.file.empty() && r.has("size")) return err("a file image has the size of its file; remove size", "size");
    if (!d.generator_args.empty() && d.generator.empty()) return err("args are generator arguments; add generator = \"...\"", "args");
    if (d.srgb && d.file.empty() && d.generator.empty())
        return err("srgb applies to file and generator images; a rendered image uses format = \"rgba8_srgb\"", "srgb");
    if (d.flip_y && d.file.empty() && d.generator.empty())
        return err("flip_y applies to file and generator images (what is uploaded)", "flip_y");
    if (d.kind == ImageKind::tex3d && d.samples > 1) return err("a 3D image cannot be multisampled", "samples");
    if (d.samples > 1 && d.mips != 1) return err("a multisampled image has exactly one mip", "mips");
    return ok_status();
}

// counter = { offset = bytes, capacity = size expression }: a word the host reads every frame.
Status parse_counter(TableReader& r, BufferDesc& d) {
    auto ct = r.table("counter", "a table { offset = bytes, capacity = elements }");
    if (!ct) return ct.error();
    if (!*ct) return ok_status();
    TableReader cr(**ct, r.file(), "buffer '" + d.name + "' counter", &d.keys, "counter.");
    CounterDesc c;
    c.loc = r.value_loc("counter");
    int offset = 0;
    if (auto s = cr.integer("offset", offset, 0, INT32_MAX); !s) return s;
    if (offset % 4) return cr.error(cr.what() + ": offset is in bytes and must be a multiple of 4 (a 32-bit word)", cr.value_loc("offset"));
    c.offset = static_cast<uint32_t>(offset);
    if (!cr.has("capacity")) return cr.error(cr.what() + " needs capacity = elements (a number or a size expression)", c.loc);
    if (auto s = cr.size("capacity", c.capacity); !s) return s;
    if (auto s = cr.finish(); !s) return s;
    d.counter = std::move(c);
    return ok_status();
}

// generator = "bvh" | "triangles": contents and size come from the build over named meshes
// (whose existence validation checks); every key that describes contents or size is refused.
Status parse_generated_buffer(TableReader& r, BufferDesc& d) {
    auto err = [&](const std::string& msg, const SourceLoc& where) { return r.error("buffer '" + d.name + "': " + msg, where); };
    if (auto s = r.choice("generator", d.generator, kBufferGenerators); !s) return s;
    for (const char* key : {"size", "data", "type", "clear", "history", "stride", "counter"})
        if (r.has(key))
            return err(std::string("'") + key + "' cannot be set on a generator buffer: its contents and size come from the build (generator = \"" +
                           d.generator + "\")",
                       r.key_loc(key));
    const toml::node* m = r.get("meshes");
    const toml::array* arr = m ? m->as_array() : nullptr;
    if (!m) return err("generator = \"" + d.generator + "\" needs meshes = [\"name\", ...] naming [meshes]", r.value_loc("generator"));
    if (!arr || arr->empty()) return r.type_error("meshes", "a non-empty array of mesh names");
    for (size_t k = 0; k < arr->size(); ++k) {
        const toml::node& e = *arr->get(k);
        if (!e.is_string()) return err("meshes must be an array of mesh names; an element is " + type_name(e), r.loc_of(e));
        std::string name = *e.value<std::string>();
        if (contains(d.meshes, name)) return err("mesh '" + name + "' is listed twice in meshes", r.loc_of(e));
        d.meshes.push_back(name);
        d.keys.map["meshes." + std::to_string(k)] = r.loc_of(e);
    }
    if (auto s = r.integer("leaf_size", d.leaf_size, 1, BufferDesc::kMaxLeafSize); !s) return s;
    if (r.has("leaf_size") && d.generator != "bvh") return err("leaf_size applies to generator = \"bvh\"", r.key_loc("leaf_size"));
    return r.finish();
}

Status parse_buffer(const toml::table& bt, const std::string& file, BufferDesc& d) {
    TableReader r(bt, file, "buffer '" + d.name + "'", &d.keys);
    if (r.has("generator")) return parse_generated_buffer(r, d);
    if (!r.has("size"))
        return r.error("buffer '" + d.name + "' needs size = bytes (a number or an expression) or generator = \"bvh\" | \"triangles\"", d.loc);
    for (const char* key : {"meshes", "leaf_size"})
        if (r.has(key))
            return r.error("buffer '" + d.name + "': '" + key + "' describes a host-built buffer; add generator = \"bvh\" or \"triangles\" (and remove size)",
                           r.key_loc(key));
    if (auto s = r.size("size", d.size); !s) return s;
    if (auto s = r.integer("stride", d.stride, 0, 1 << 20); !s) return s;
    if (r.has("clear")) {
        uint32_t c = 0;
        if (auto s = r.uinteger("clear", c); !s) return s;
        d.clear = c;
    }
    if (auto s = r.numbers("data", d.data, 0, size_t(1) << 24); !s) return s;
    if (auto s = r.choice("type", d.data_type, {"float", "int", "uint"}); !s) return s;
    if (auto s = r.boolean("history", d.history); !s) return s;
    if (auto s = parse_counter(r, d); !s) return s;
    if (auto s = r.finish(); !s) return s;
    if (r.has("type") && d.data.empty()) return r.error("buffer '" + d.name + "': type describes data; add data = [...]", r.value_loc("type"));
    // Integer data must be representable exactly in 32 bits of the declared type.
    for (double x : d.data) {
        bool ok = true;
        if (d.data_type == "int") ok = x == std::floor(x) && x >= -2147483648.0 && x <= 2147483647.0;
        if (d.data_type == "uint") ok = x == std::floor(x) && x >= 0 && x <= 4294967295.0;
        if (!ok) {
            char b[64];
            std::snprintf(b, sizeof b, "%g", x);
            return r.error("buffer '" + d.name + "': data value " + b + " is not a 32-bit " + d.data_type, r.value_loc("data"));
        }
    }
    return ok_status();
}

Status parse_mesh(const toml::table& mt, const std::string& file, MeshDesc& d) {
    TableReader r(mt, file, "mesh '" + d.name + "'", &d.keys);
    if (auto s = r.choice("generator", d.generator, kMeshGenerators); !s) return s;
    if (auto s = r.str("file", d.file); !s) return s;
    if (auto s = r.integer("instances", d.instances, 1, 1000000); !s) return s;
    if (d.generator.empty() == d.file.empty()) return r.error("mesh '" + d.name + "' needs exactly one of generator or file", d.loc);
    if (!d.file.empty()) {
        std::string ext = std::filesystem::path(d.file).extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (ext != ".obj" && ext != ".gltf" && ext != ".glb")
            return r.error("mesh '" + d.name + "': file must be .obj, .gltf or .glb", r.value_loc("file"));
    }
    if (r.has("simplify")) {
        d.simplify.emplace();
        if (auto s = parse_mesh_simplify(r, *d.simplify); !s) return s;
    }
    // Every other key is a numeric generator argument.
    for (auto&& [ak, av] : mt) {
        std::string key(ak.str());
        if (key == "generator" || key == "file" || key == "instances" || key == "simplify") continue;
        if (!contains(kMeshArgs, key)) {
            Error e = r.error("mesh '" + d.name + "': unknown key '" + key + "'", r.key_loc(key));
            std::vector<std::string> valid = {"generator", "file", "instances", "simplify"};
            valid.insert(valid.end(), kMeshArgs.begin(), kMeshArgs.end());
            suggest(e, key, valid, "keys");
            return e;
        }
        if (!d.file.empty()) return r.error("mesh '" + d.name + "': '" + key + "' is a generator argument; a file mesh takes none", r.key_loc(key));
        double x = 0;
        if (auto s = r.number(key, x); !s) return s;
        if (!(x > 0)) return r.error("mesh '" + d.name + "': " + key + " must be > 0", r.value_loc(key));
        d.args[key] = x;
    }
    return ok_status();
}

} // namespace

Status parse_images(const toml::table& t, const std::string& file, GraphDesc& g) {
    TableReader sec(t, file, "[images]");
    for (auto&& [k, v] : t) {
        ImageDesc d;
        d.name = std::string(k.str());
        if (auto s = check_name(sec, d.name, "image"); !s) return s;
        d.loc = sec.key_loc(d.name);
        const toml::table* it = v.as_table();
        if (!it) return sec.error("image '" + d.name + "' must be a table { format = ..., size = ... }, not " + type_name(v), sec.loc_of(v));
        if (auto s = parse_image(*it, file, d); !s) return named(s, d.name);
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
        if (!bt) return sec.error("buffer '" + d.name + "' must be a table { size = ... }, not " + type_name(v), sec.loc_of(v));
        if (auto s = parse_buffer(*bt, file, d); !s) return named(s, d.name);
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
        if (!mt) return sec.error("mesh '" + d.name + "' must be a table { generator = ... }, not " + type_name(v), sec.loc_of(v));
        if (auto s = parse_mesh(*mt, file, d); !s) return named(s, d.name);
        g.meshes.push_back(std::move(d));
    }
    return ok_status();
}

} // namespace pl::graph
