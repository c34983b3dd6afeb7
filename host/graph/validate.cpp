#include "graph/validate.hpp"

#include "vk/formats.hpp"

#include <set>

namespace fs = std::filesystem;

namespace pl::graph {

namespace {

// Limits: large enough for any course technique, small enough that a typo cannot make the host
// allocate until the machine swaps.
constexpr int64_t kMaxDim = 16384, kMax3D = 2048;
constexpr int64_t kMaxImageBytes = int64_t(2) << 30, kMaxBufferBytes = int64_t(1) << 30;

Error ref_error(const std::string& what, const std::string& name, const SourceLoc& loc, const std::string& pass,
                const std::vector<std::string>& valid) {
    Error e = make_error(what + " '" + name + "' does not exist", loc);
    e.pass = pass;
    e.resource = name;
    suggest(e, name, valid, "declared", "none are declared");
    return e;
}

std::string human_bytes(double b) {
    char buf[64];
    if (b >= double(1ull << 30)) std::snprintf(buf, sizeof buf, "%.1f GiB", b / double(1ull << 30));
    else std::snprintf(buf, sizeof buf, "%.1f MiB", b / double(1ull << 20));
    return buf;
}

} // namespace

fs::path resolve_shader_path(const std::string& file, const std::vector<fs::path>& search) {
    std::error_code ec;
    for (const auto& d : search)
        if (fs::is_regular_file(d / file, ec)) return d / file;
    return {};
}

Status validate_graph(GraphDesc& g, const ValidateOptions& opt) {
    std::vector<std::string> images, buffers, meshes, params, samplable;
    std::set<std::string> names;
    for (const auto& i : g.images) {
        if (!names.insert(i.name).second) {
            Error e = make_error("the name '" + i.name + "' is used twice", i.loc);
            return e;
        }
        images.push_back(i.name);
    }
    for (const auto& b : g.buffers) {
        if (!names.insert(b.name).second) return make_error("the name '" + b.name + "' is used by an image and a buffer", b.loc);
        buffers.push_back(b.name);
    }
    for (const auto& i : g.images)
        if (i.history && names.count(i.name + "_prev"))
            return make_error("'" + i.name + "_prev' is reserved for the previous frame of history image '" + i.name + "'", i.loc);
    for (const auto& m : g.meshes) meshes.push_back(m.name);
    for (const auto& p : g.params) params.push_back(p.name);

    SizeEnv env;
    env.view_w = g.view.size[0];
    env.view_h = g.view.size[1];
    for (const auto& p : g.params) env.params[p.name] = p.value[0];

    auto format_names = vk::format_names();
    for (auto& i : g.images) {
        auto err = [&](const std::string& msg, SourceLoc l) {
            Error e = make_error("image '" + i.name + "': " + msg, l.known() ? l : i.loc);
            e.resource = i.name;
            return e;
        };
        if (!i.alias.empty()) {
            const ImageDesc* target = g.find_image(i.alias);
            if (!target) return ref_error("alias target image", i.alias, i.loc, "", images);
            if (!target->alias.empty()) return err("an alias cannot point at another alias", i.loc);
            continue;
        }
        const vk::FormatInfo* f = vk::find_format(i.format);
        if (!f) {
            Error e = err("unknown format '" + i.format + "'", i.format_loc);
            suggest(e, i.format, format_names, "formats");
            return e;
        }
        if (!i.file.empty() && !i.generator.empty()) return err("has both file and generator; choose one", i.loc);
        if (!i.file.empty()) {
            std::error_code ec;
            if (!fs::is_regular_file(g.dir / i.file, ec)) return err("file '" + i.file + "' not found next to preset.toml", i.loc);
            continue;
        }
        if (i.samples != 1 && i.samples != 2 && i.samples != 4 && i.samples != 8) return err("samples must be 1, 2, 4 or 8", i.loc);
        if (i.samples > 1 && i.mips != 1) return err("a multisampled image has exactly one mip", i.loc);
        if (i.layers < 1 || i.layers > 2048) return err("layers must be 1..2048", i.loc);
        SizeExpr size = i.size;
        if (size.empty()) {
            if (i.generator.empty()) size.text = "view";
            else size.literal = {256, 256};
        }
        int dims = i.kind == ImageKind::tex3d ? 3 : 2;
        auto ext = eval_extent(size, env, dims);
        if (!ext) {
            Error e = ext.error();
            e.resource = i.name;
            return e;
        }
        int64_t limit = dims == 3 ? kMax3D : kMaxDim;
        std::string text = std::to_string(ext->w) + "x" + std::to_string(ext->h) + (dims == 3 ? "x" + std::to_string(ext->d) : "");
        if (ext->w < 1 || ext->h < 1 || ext->d < 1)
            return err("size evaluates to " + text + "; every side must be at least 1", size.loc);
        if (ext->w > limit || ext->h > limit || ext->d > limit)
            return err("size evaluates to " + text + "; sides are limited to " + std::to_string(limit), size.loc);
        if (i.kind == ImageKind::cube && ext->w != ext->h) return err("a cube image must be square, not " + text, size.loc);
        int64_t layers = i.kind == ImageKind::cube ? 6 : i.layers;
        double bytes = double(ext->w) * double(ext->h) * double(ext->d) * layers * f->bytes_per_texel * i.samples * (i.history ? 2 : 1) *
                       (i.mips == 1 ? 1.0 : 4.0 / 3.0);
        if (bytes > double(kMaxImageBytes))
            return err("would need " + human_bytes(bytes) + " (limit " + human_bytes(double(kMaxImageBytes)) + ")", size.loc);
    }
    for (const auto& b : g.buffers) {
        auto sz = eval_scalar(b.size, env);
        if (!sz) {
            Error e = sz.error();
            e.resource = b.name;
            return e;
        }
        if (*sz < 4 || *sz > kMaxBufferBytes) {
            Error e = make_error("buffer '" + b.name + "': size evaluates to " + std::to_string(*sz) +
                                     " bytes; it must be between 4 bytes and " + human_bytes(double(kMaxBufferBytes)),
                                 b.size.loc);
            e.resource = b.name;
            return e;
        }
    }

    for (auto& p : g.passes) {
        auto perr = [&](const std::string& msg, const SourceLoc& l) {
            Error e = make_error(msg, l.known() ? l : p.loc);
            e.pass = p.name;
            return e;
        };
        auto need_image = [&](const std::string& n, const SourceLoc& l) -> Status {
            if (g.find_image(n)) return ok_status();
            return ref_error("image", n, l.known() ? l : p.loc, p.name, images);
        };
        auto need_shader = [&](const ShaderRef& s, const char* what) -> Status {
            if (s.empty()) return ok_status();
            if (resolve_shader_path(s.file, opt.search_dirs).empty()) {
                Error e = perr(std::string(what) + " shader '" + s.file + "' not found", s.loc);
                for (const auto& d : opt.search_dirs) e.notes.push_back("looked in " + d.string());
                return e;
            }
            return ok_status();
        };
        bool raster = p.kind == PassKind::fullscreen || p.kind == PassKind::draw;
        if (p.kind == PassKind::fullscreen && p.fragment.empty()) return perr("a fullscreen pass needs fragment = \"file.frag\"", p.loc);
        if (p.kind == PassKind::draw && p.vertex.empty()) return perr("a draw pass needs vertex = \"file.vert\"", p.loc);
        if (p.kind == PassKind::compute) {
            if (p.compute.empty()) return perr("a compute pass needs compute = \"file.comp\"", p.loc);
            if (p.groups.empty() == p.threads.empty() && p.indirect.empty())
                return perr("a compute pass needs exactly one of groups or threads (or indirect)", p.loc);
        }
        if (!raster && (!p.vertex.empty() || !p.fragment.empty() || !p.geometry.empty()))
            return perr("a " + std::string(p.kind == PassKind::compute ? "compute" : "transfer") + " pass takes no vertex/fragment shaders", p.loc);
        if (p.kind != PassKind::compute && !p.compute.empty()) return perr("only compute passes take compute = ...", p.compute.loc);
        if ((p.kind == PassKind::blit || p.kind == PassKind::copy) && (p.src.empty() || p.dst.empty()))
            return perr("a blit/copy pass needs src and dst", p.loc);
        if ((p.kind == PassKind::mips || p.kind == PassKind::clear) && p.image.empty())
            return perr("a mips/clear pass needs image = \"name\"", p.loc);
        if (raster && p.targets.empty() && !p.depth) return perr("the pass renders into nothing: add targets or depth", p.loc);
        for (const auto* s : {&p.vertex, &p.fragment, &p.geometry, &p.tess_control, &p.tess_eval, &p.compute})
            if (auto st = need_shader(*s, "the"); !st) return st;
        std::set<std::string> used;
        for (const auto& t : p.targets) {
            if (auto s = need_image(t.image, t.loc); !s) return s;
            const ImageDesc* d = g.find_image(t.image);
            const ImageDesc* base = d->alias.empty() ? d : g.find_image(d->alias);
            const vk::FormatInfo* f = vk::find_format(base->format);
            if (f && f->is_depth) return perr("'" + t.image + "' has a depth format; use depth = \"" + t.image + "\"", t.loc);
            if (!used.insert(base->name).second) return perr("image '" + t.image + "' is attached twice", t.loc);
            if (!t.resolve.empty())
                if (auto s = need_image(t.resolve, t.loc); !s) return s;
        }
        if (p.depth) {
            if (auto s = need_image(p.depth->target.image, p.depth->target.loc); !s) return s;
            const ImageDesc* d = g.find_image(p.depth->target.image);
            const vk::FormatInfo* f = vk::find_format(d->alias.empty() ? d->format : g.find_image(d->alias)->format);
            if (f && !f->is_depth) return perr("depth image '" + d->name + "' has colour format " + d->format + "; use d32, d24s8 or d32s8", p.depth->loc);
            if (p.stencil.enable && f && !f->has_stencil) return perr("stencil needs a depth image with stencil (d24s8 or d32s8)", p.stencil.loc);
            if (used.count(d->name)) return perr("image '" + d->name + "' is both a colour target and the depth target", p.depth->loc);
        } else if (p.stencil.enable) {
            return perr("stencil needs a depth attachment with a stencil format", p.stencil.loc);
        }
        for (const auto* n : {&p.src, &p.dst, &p.image}) {
            if (n->empty()) continue;
            bool is_buffer = g.find_buffer(*n) != nullptr;
            if (is_buffer && (p.kind == PassKind::copy || p.kind == PassKind::clear)) continue;
            if (auto s = need_image(*n, p.loc); !s) return s;
        }
        if (!p.src.empty() && p.src == p.dst) return perr("src and dst are the same image", p.loc);
        if (!p.mesh.empty() && !g.find_mesh(p.mesh)) return ref_error("mesh", p.mesh, p.loc, p.name, meshes);
        if (!p.indirect.empty() && !g.find_buffer(p.indirect)) return ref_error("indirect buffer", p.indirect, p.loc, p.name, buffers);
        if (p.kind == PassKind::draw && p.mesh.empty() && p.vertex_count <= 0 && p.indirect.empty())
            return perr("a draw pass without mesh needs vertex_count > 0 (vertices from gl_VertexIndex)", p.loc);
        for (const auto& s : p.swap)
            if (!g.find_image(s)) return ref_error("swap image", s, p.swap_loc, p.name, images);
        for (const auto& [shader_name, res] : p.bind)
            if (!g.find_image(res) && !g.find_buffer(res)) {
                std::vector<std::string> all = images;
                all.insert(all.end(), buffers.begin(), buffers.end());
                return ref_error("bind target", res, p.bind_loc, p.name, all);
            }
    }
    std::set<std::string> pass_names;
    for (const auto& t : g.tests) {
        for (const auto& [k, v] : t.set)
            if (!g.find_param(k)) return ref_error("param", k, t.loc, "", params);
        if (!t.pass.empty() && !g.find_image(t.pass)) return ref_error("image", t.pass, t.loc, "", images);
    }
    // Default output: the first colour target of the last pass that has one.
    if (g.output.empty()) {
        for (auto it = g.passes.rbegin(); it != g.passes.rend() && g.output.empty(); ++it)
            if (!it->targets.empty()) g.output = it->targets.front().image;
        if (g.output.empty() && !g.images.empty()) g.output = g.images.back().name;
        if (g.output.empty()) return make_error("the graph has no image to output", {g.file.string(), 1, 1});
    } else if (!g.find_image(g.output)) {
        return ref_error("output image", g.output, g.output_loc, "", images);
    }
    return ok_status();
}

} // namespace pl::graph
