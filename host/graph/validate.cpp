// Graph-wide checks: names, resources, output, tests; passes are validate_passes.cpp and sizes
// validate_sizes.cpp. The first error is returned: later ones are often consequences of it.
#include "graph/validate_parts.hpp"

#include "vk/clear_value.hpp"
#include "graph/camera_values.hpp"
#include "vk/formats.hpp"

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <map>

namespace fs = std::filesystem;

namespace pl::graph {

std::vector<std::string> DeclaredNames::resources() const {
    std::vector<std::string> all = images;
    all.insert(all.end(), buffers.begin(), buffers.end());
    return all;
}

Error ref_error(const std::string& what, const std::string& name, const SourceLoc& loc, const std::string& pass,
                const std::vector<std::string>& valid, const std::string& label) {
    Error e = make_error(what + " '" + name + "' does not exist", loc);
    e.pass = pass;
    e.resource = name;
    suggest(e, name, valid, label, "none are declared");
    return e;
}

std::string human_bytes(double b) {
    char buf[64];
    if (b >= double(1ull << 30)) std::snprintf(buf, sizeof buf, "%.1f GiB", b / double(1ull << 30));
    else if (b >= double(1ull << 20)) std::snprintf(buf, sizeof buf, "%.1f MiB", b / double(1ull << 20));
    else std::snprintf(buf, sizeof buf, "%.0f bytes", b);
    return buf;
}

fs::path passes_dir() {
    if (const char* root = std::getenv("PASSLAB_ROOT"); root && *root) return fs::path(root) / "passes";
    return fs::path(PASSLAB_SOURCE_DIR) / "passes";
}

std::vector<fs::path> default_search_dirs(const GraphDesc& g) { return {g.dir, passes_dir()}; }

fs::path resolve_shader_path(const std::string& file, const std::vector<fs::path>& search) {
    if (file.empty()) return {};
    std::error_code ec;
    for (const auto& d : search)
        if (fs::is_regular_file(d / file, ec)) return d / file;
    return {};
}

fs::path resolve_shader_path(const GraphDesc& g, const std::string& file, const std::vector<fs::path>& search) {
    return resolve_shader_path(file, search.empty() ? default_search_dirs(g) : search);
}

std::string effective_format(const GraphDesc& g, const ImageDesc& d) {
    if (!d.alias.empty()) {
        const ImageDesc* t = g.find_image(d.alias);
        return t && t != &d && t->alias.empty() ? effective_format(g, *t) : d.format;
    }
    // The one definition (exec creates images with it): a written format wins; files and
    // generators pick their own.
    if (d.format_loc.known() || (d.file.empty() && d.generator.empty())) return d.format;
    if (!d.file.empty()) {
        std::string ext = fs::path(d.file).extension().string();
        std::transform(ext.begin(), ext.end(), ext.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
        if (ext == ".exr" || ext == ".hdr") return "rgba32f";
    }
    return d.srgb ? "rgba8_srgb" : d.format;
}

std::string default_output(const GraphDesc& g) {
    auto colour = [&](const std::string& name) {
        const ImageDesc* d = g.find_image(name);
        if (!d) return false;
        const vk::FormatInfo* f = vk::find_format(effective_format(g, *d));
        return f && !f->is_depth;
    };
    for (auto it = g.passes.rbegin(); it != g.passes.rend(); ++it) {
        if (!it->enabled) continue;
        if ((it->kind == PassKind::fullscreen || it->kind == PassKind::draw) && !it->targets.empty()) {
            const AttachmentRef& t = it->targets.front();
            if (!t.resolve.empty() && colour(t.resolve)) return t.resolve;
            if (colour(t.image)) return t.image;
        }
        if ((it->kind == PassKind::blit || it->kind == PassKind::copy) && colour(it->dst)) return it->dst;
    }
    for (auto it = g.images.rbegin(); it != g.images.rend(); ++it)
        if (colour(it->name)) return it->name;
    return {};
}

namespace {

Status check_names(const GraphDesc& g, DeclaredNames& n) {
    // Images and buffers share one namespace: a shader binds either by the name it declares.
    std::map<std::string, SourceLoc> seen;
    auto add = [&](const std::string& name, const SourceLoc& loc, const char* what) -> Status {
        auto [it, fresh] = seen.emplace(name, loc);
        if (fresh) return ok_status();
        Error e = make_error("the name '" + name + "' is used twice (images and buffers share one namespace)", loc);
        e.resource = name;
        e.notes.push_back(std::string("this ") + what + "; the first is at " + it->second.str());
        return e;
    };
    for (const auto& i : g.images) {
        if (auto s = add(i.name, i.loc, "image"); !s) return s;
        n.images.push_back(i.name);
    }
    for (const auto& b : g.buffers) {
        if (auto s = add(b.name, b.loc, "buffer"); !s) return s;
        n.buffers.push_back(b.name);
    }
    // `<name>_prev` is how shaders read last frame's contents of a history resource.
    auto reserve = [&](const std::string& name, bool history, const SourceLoc& loc) -> Status {
        if (!history) return ok_status();
        auto it = seen.find(name + "_prev");
        if (it == seen.end()) return ok_status();
        Error e = make_error("'" + name + "_prev' is reserved for the previous frame of history resource '" + name + "'", it->second);
        e.resource = name + "_prev";
        e.notes.push_back("'" + name + "' is declared with history = true at " + loc.str());
        return e;
    };
    for (const auto& i : g.images)
        if (auto s = reserve(i.name, i.history, i.loc); !s) return s;
    for (const auto& b : g.buffers)
        if (auto s = reserve(b.name, b.history, b.loc); !s) return s;
    std::map<std::string, SourceLoc> meshes;
    for (const auto& m : g.meshes) {
        if (auto [it, fresh] = meshes.emplace(m.name, m.loc); !fresh)
            return make_error("a mesh named '" + m.name + "' already exists (first at " + it->second.str() + ")", m.loc);
        n.meshes.push_back(m.name);
    }
    for (const auto& p : g.params) n.params.push_back(p.name);
    return ok_status();
}

Status check_images(const GraphDesc& g, const DeclaredNames& n) {
    for (const auto& i : g.images) {
        auto err = [&](const std::string& msg, const std::string& key) {
            Error e = make_error("image '" + i.name + "': " + msg, i.keys.at(key, i.loc));
            e.resource = i.name;
            return e;
        };
        if (!i.alias.empty()) {
            const ImageDesc* target = g.find_image(i.alias);
            if (!target || target == &i) {
                std::vector<std::string> others;
                for (const auto& o : n.images)
                    if (o != i.name) others.push_back(o);
                Error e = ref_error("alias target image", i.alias, i.keys.at("alias", i.loc), "", others, "images");
                e.message = "image '" + i.name + "': " + e.message;
                return e;
            }
            if (!target->alias.empty()) return err("'" + i.alias + "' is itself an alias; point at '" + target->alias + "'", "alias");
            continue;
        }
        const vk::FormatInfo* f = vk::find_format(i.format);
        if (!f) {
            Error e = err("unknown format '" + i.format + "'", "format");
            suggest(e, i.format, vk::format_names(), "formats");
            return e;
        }
        const vk::FormatInfo* ef = vk::find_format(effective_format(g, i));
        if (!i.file.empty()) {
            std::error_code ec;
            if (fs::exists(g.dir / i.file, ec) && !fs::is_regular_file(g.dir / i.file, ec)) {
                // A FIFO or /dev/zero would block or never end the image reader.
                Error e = err("file '" + i.file + "' is not a regular file (a FIFO, a device or a folder): only regular files are read", "file");
                return e;
            }
            if (!fs::is_regular_file(g.dir / i.file, ec)) {
                Error e = err("file '" + i.file + "' not found", "file");
                e.notes.push_back("looked for " + (g.dir / i.file).string() + " (files are relative to the preset folder)");
                return e;
            }
        }
        if (!i.file.empty() && !i.generator.empty()) return err("has both file and generator; choose one", "generator");
        if (i.samples != 1 && i.samples != 2 && i.samples != 4 && i.samples != 8) return err("samples must be 1, 2, 4 or 8", "samples");
        if (i.samples > 1 && i.mips != 1) return err("a multisampled image has exactly one mip", "mips");
        if (i.samples > 1 && (!i.file.empty() || !i.generator.empty())) return err("a file or generator image cannot be multisampled", "samples");
        if (i.kind == ImageKind::tex3d && i.samples > 1) return err("a 3D image cannot be multisampled", "samples");
        if (i.layers < 1) return err("layers must be at least 1", "layers");
        if (ef && ef->compressed()) {
            // Filled only by a copy from a buffer of blocks (see passes' copy); one mip, no MSAA.
            if (!i.file.empty() || !i.generator.empty()) return err("a file or generator image cannot have a block-compressed format (fill it by a copy from a buffer)", "format");
            if (i.kind == ImageKind::tex3d) return err("a 3D image cannot have a block-compressed format", "format");
            if (i.samples > 1) return err("a block-compressed image cannot be multisampled", "samples");
            if (i.mips != 1) return err("a block-compressed image has one mip here (the copy fills mip 0)", "mips");
            if (i.history) return err("a block-compressed image cannot be a history image", "history");
            if (i.clear) return err("a block-compressed image cannot be cleared", "clear");
        }
        if (ef && i.clear && !ef->is_depth)
            if (std::string why = vk::clear_value_problem(*ef, *i.clear); !why.empty()) return err(why, "clear");
        if (ef && ef->is_depth) {
            if (i.kind == ImageKind::tex3d) return err("a 3D image cannot have a depth format", "format");
            if (!i.file.empty() || !i.generator.empty()) return err("a file or generator image cannot have a depth format", "format");
        }
    }
    return ok_status();
}

// The value of a test `set` must have the param's type and lie within its range.
Status check_set_value(const ParamDesc& p, const Value& v, const SourceLoc& loc, const std::string& test) {
    auto bad = [&](const std::string& why) {
        Error e = make_error("test '" + test + "': set." + p.name + " " + why, loc);
        e.resource = p.name;
        e.notes.push_back("param '" + p.name + "' is declared at " + p.loc.str());
        return e;
    };
    std::vector<double> nums;
    switch (p.type) {
    case ParamType::boolean:
        if (!std::holds_alternative<bool>(v)) return bad("must be true or false (the param is a bool)");
        return ok_status();
    case ParamType::enumeration: {
        const std::string* s = std::get_if<std::string>(&v);
        if (!s) return bad("must be one of the options (a string)");
        if (std::find(p.options.begin(), p.options.end(), *s) == p.options.end()) {
            Error e = bad("is \"" + *s + "\", not one of the options");
            suggest(e, *s, p.options, "options", {}, '"');
            return e;
        }
        return ok_status();
    }
    case ParamType::f32:
    case ParamType::i32:
        if (!std::holds_alternative<double>(v)) return bad("must be a number");
        nums = {std::get<double>(v)};
        if (p.type == ParamType::i32 && nums[0] != static_cast<double>(static_cast<long long>(nums[0])))
            return bad("must be an integer (the param is an int)");
        break;
    default: {
        const auto* vec = std::get_if<std::vector<double>>(&v);
        if (!vec || static_cast<int>(vec->size()) != p.components())
            return bad("must be " + std::to_string(p.components()) + " numbers");
        nums = *vec;
    }
    }
    for (double x : nums) {
        char b[64];
        if (p.min && x < *p.min) {
            std::snprintf(b, sizeof b, "value %g is below its min %g", x, *p.min);
            return bad(b);
        }
        if (p.max && x > *p.max) {
            std::snprintf(b, sizeof b, "value %g is above its max %g", x, *p.max);
            return bad(b);
        }
    }
    return ok_status();
}

Status check_tests(const GraphDesc& g, const DeclaredNames& n, const SizeEnv& env) {
    for (size_t k = 0; k < g.tests.size(); ++k) {
        const TestDesc& t = g.tests[k];
        for (size_t j = 0; j < k; ++j)
            if (g.tests[j].name == t.name)
                return make_error("a test named '" + t.name + "' already exists (first at " + g.tests[j].loc.str() + ")", t.loc);
        for (const auto& [k, v] : t.set) {
            SourceLoc loc = t.keys.at("set." + k, t.loc);
            const ParamDesc* p = g.find_param(k);
            if (!p) {
                Error e = ref_error("param", k, loc, "", n.params, "params");
                e.message = "test '" + t.name + "': " + e.message;
                return e;
            }
            if (auto s = check_set_value(*p, v, loc, t.name); !s) return s;
        }
        auto need_image = [&](const std::string& name, const SourceLoc& loc) -> Status {
            if (name.empty() || g.find_image(name)) return ok_status();
            Error e = ref_error("image", name, loc, "", n.images, "images");
            e.message = "test '" + t.name + "': " + e.message;
            return e;
        };
        if (auto s = need_image(t.pass, t.keys.at("pass", t.loc)); !s) return s;
        for (const auto& c : t.checks)
            if (auto s = validate_check(g, n, t, c, env); !s) return s;
    }
    return ok_status();
}

SizeEnv base_env(const GraphDesc& g, const ValidateOptions& opt) {
    return make_env(g, opt.view_size ? *opt.view_size : g.view.size);
}

// The environment a test renders in: its size (else [view].size, whatever --size says) and its
// param overrides over `env`.
SizeEnv test_env(const GraphDesc& g, const TestDesc& t, const SizeEnv& env) {
    SizeEnv te = env;
    std::array<int, 2> size = t.size ? *t.size : g.view.size;
    te.view_w = size[0], te.view_h = size[1];
    for (const auto& [k, v] : t.set) {
        const ParamDesc* p = g.find_param(k);
        if (const double* d = std::get_if<double>(&v)) te.params[k] = *d;
        else if (const bool* b = std::get_if<bool>(&v)) te.params[k] = *b ? 1 : 0;
        else if (const auto* vec = std::get_if<std::vector<double>>(&v); vec && !vec->empty())
            te.params[k] = (*vec)[0], te.vectors[k] = *vec;
        else if (const std::string* s = std::get_if<std::string>(&v); s && p)
            te.params[k] = static_cast<double>(std::find(p->options.begin(), p->options.end(), *s) - p->options.begin());
        // Camera expressions read vector params whole (params.dir); scalars are 1-vectors.
        if (!std::holds_alternative<std::vector<double>>(v)) te.vectors[k] = {te.params[k]};
    }
    return te;
}

// Host-built buffers (generator = "bvh" | "triangles") name the meshes they are built from.
Status check_buffer_meshes(const GraphDesc& g, const DeclaredNames& n) {
    for (const auto& b : g.buffers)
        for (size_t k = 0; k < b.meshes.size(); ++k)
            if (!g.find_mesh(b.meshes[k])) {
                Error e = ref_error("buffer '" + b.name + "': mesh", b.meshes[k], b.keys.at("meshes." + std::to_string(k), b.loc), "",
                                    n.meshes, "meshes");
                e.resource = b.name;
                return e;
            }
    return ok_status();
}

} // namespace

Status validate_graph(const GraphDesc& g, const ValidateOptions& opt) {
    DeclaredNames names;
    if (auto s = check_names(g, names); !s) return s;
    if (auto s = check_images(g, names); !s) return s;
    if (auto s = check_buffer_meshes(g, names); !s) return s;
    SizeEnv env = base_env(g, opt);
    if (auto s = validate_sizes(g, env, {}, {}); !s) return s;
    if (auto s = validate_passes(g, opt, names); !s) return s;
    if (auto s = validate_groups(g, names); !s) return s;
    if (auto s = validate_cameras(g, env, nullptr); !s) return s;

    if (!g.output.empty()) {
        if (!g.find_image(g.output)) {
            SourceLoc loc = g.output_loc.known() ? g.output_loc : SourceLoc{g.file.string(), 0, 0};
            Error e = ref_error("output image", g.output, loc, "", names.images, "images");
            if (g.find_buffer(g.output)) e.message = "[output]: '" + g.output + "' is a buffer; the output is an image";
            return e;
        }
    } else if (default_output(g).empty()) {
        Error e = make_error("the graph has no colour image to output", {g.file.string(), 0, 0});
        e.hint = "declare an image in [images] and render into it";
        return e;
    }

    if (auto s = check_tests(g, names, env); !s) return s;
    for (const auto& t : g.tests) {
        bool overrides = t.size || !t.set.empty() || !t.cameras.empty();
        if (overrides && !opt.per_test_sizes) continue;  // its sizes are not known here
        SizeEnv te = test_env(g, t, env);
        if (overrides) {
            std::string context = "in test '" + t.name + "' (" + std::to_string(te.view_w) + "x" + std::to_string(te.view_h) + ")";
            if (auto s = validate_sizes(g, te, context, t.loc); !s) return s;
            if (auto s = validate_cameras(g, te, &t); !s) return s;
        }
        if (opt.test_reads)
            if (auto s = validate_test_reads(g, t, te); !s) return s;
    }
    return ok_status();
}

Status validate_graph(GraphDesc& g, const ValidateOptions& opt) {
    if (auto s = validate_graph(static_cast<const GraphDesc&>(g), opt); !s) return s;
    if (g.output.empty()) g.output = default_output(g);
    return ok_status();
}

} // namespace pl::graph
