// Per-pass checks: what each kind needs and what it cannot use, shader files, references to
// images, buffers and meshes, attachment formats and sharing.
#include "graph/validate_parts.hpp"

#include "vk/clear_value.hpp"
#include "vk/formats.hpp"

#include <algorithm>
#include <set>

namespace fs = std::filesystem;

namespace pl::graph {

namespace {


// The keys each kind uses besides name, kind, enabled, bake, repeat and swap. A key written on a kind
// that ignores it is an error: `groups` on a fullscreen pass is a misunderstanding to point out,
// not something to drop silently.
const std::set<std::string>& kind_keys(PassKind k) {
    static const std::set<std::string> raster_common = {"targets", "depth", "stencil", "blend", "clear", "defines", "bind", "camera"};
    static const std::map<PassKind, std::set<std::string>> keys = [] {
        std::map<PassKind, std::set<std::string>> m;
        m[PassKind::fullscreen] = raster_common;
        m[PassKind::fullscreen].insert({"vertex", "fragment"});
        m[PassKind::draw] = raster_common;
        m[PassKind::draw].insert({"vertex", "fragment", "geometry", "tess_control", "tess_eval", "mesh", "vertex_count",
                                  "instances", "indirect", "topology", "patch_points", "cull", "front_face", "polygon",
                                  "line_width"});
        m[PassKind::compute] = {"compute", "groups", "threads", "indirect", "defines", "bind", "camera"};
        m[PassKind::blit] = {"src", "dst", "filter"};
        m[PassKind::copy] = {"src", "dst"};
        m[PassKind::mips] = {"image"};
        m[PassKind::clear] = {"image", "clear"};
        return m;
    }();
    return keys.at(k);
}

struct PassChecker {
    const GraphDesc& g;
    const DeclaredNames& names;
    const PassDesc& p;
    std::vector<fs::path> search;

    Error err(const std::string& msg, const SourceLoc& l, const std::string& resource = {}) const {
        Error e = make_error(msg, l.known() ? l : p.loc);
        e.pass = p.name;
        e.resource = resource;
        return e;
    }
    SourceLoc at(const std::string& key) const { return p.keys.at(key, p.loc); }

    const ImageDesc* base(const ImageDesc* d) const { return d && !d->alias.empty() ? g.find_image(d->alias) : d; }
    // NAME_prev of a history image (or of an alias of one) or history buffer: last frame's contents.
    bool is_previous_frame(const std::string& res) const {
        if (res.size() <= 5 || !res.ends_with("_prev")) return false;
        const std::string name = res.substr(0, res.size() - 5);
        const ImageDesc* i = base(g.find_image(name));
        const BufferDesc* b = g.find_buffer(name);
        return (i && i->history) || (b && b->history);
    }
    const vk::FormatInfo* format(const ImageDesc* d) const { return d ? vk::find_format(effective_format(g, *d)) : nullptr; }

    Status need_image(const std::string& n, const SourceLoc& l, const char* what = "image") const {
        if (g.find_image(n)) return ok_status();
        Error e = ref_error(what, n, l.known() ? l : p.loc, p.name, names.images, "images");
        if (g.find_buffer(n)) {
            e.message = "'" + n + "' is a buffer; " + std::string(what) + " must be an image";
            e.hint.clear();
        }
        return e;
    }
    Status need_buffer(const std::string& n, const SourceLoc& l, const char* what) const {
        if (g.find_buffer(n)) return ok_status();
        return ref_error(what, n, l.known() ? l : p.loc, p.name, names.buffers, "buffers");
    }

    Status kind_and_keys() const {
        const auto& allowed = kind_keys(p.kind);
        static const std::set<std::string> always = {"name", "kind", "enabled", "bake", "repeat", "swap"};
        for (const auto& [key, loc] : p.keys.map) {
            std::string top = key.substr(0, key.find('.'));
            if (always.count(top) || allowed.count(top)) continue;
            std::string msg = "'" + top + "' does not apply to a " + std::string(kind_name(p.kind)) + " pass";
            Error e = err(msg, loc);
            // Say which kind the key belongs to: often the kind is what is wrong.
            for (PassKind k : {PassKind::fullscreen, PassKind::draw, PassKind::compute, PassKind::blit, PassKind::copy,
                               PassKind::mips, PassKind::clear})
                if (kind_keys(k).count(top)) {
                    e.hint = "'" + top + "' belongs to kind = \"" + kind_name(k) + "\"";
                    break;
                }
            return e;
        }
        auto shader_not_allowed = [&](const ShaderRef& s, const char* key) -> Status {
            if (s.empty() || allowed.count(key)) return ok_status();
            return err("a " + std::string(kind_name(p.kind)) + " pass takes no " + key + " shader", s.loc);
        };
        for (auto [ref, key] : {std::pair{&p.vertex, "vertex"}, {&p.fragment, "fragment"}, {&p.geometry, "geometry"},
                                {&p.tess_control, "tess_control"}, {&p.tess_eval, "tess_eval"}, {&p.compute, "compute"}})
            if (auto s = shader_not_allowed(*ref, key); !s) return s;
        switch (p.kind) {
        case PassKind::fullscreen:
            if (p.fragment.empty()) return err("a fullscreen pass needs fragment = \"file.frag\"", p.loc);
            break;
        case PassKind::draw:
            if (p.vertex.empty()) return err("a draw pass needs vertex = \"file.vert\"", p.loc);
            if (p.tess_control.empty() != p.tess_eval.empty())
                return err("tessellation needs both tess_control and tess_eval", (p.tess_control.empty() ? p.tess_eval : p.tess_control).loc);
            if (!p.tess_eval.empty() && p.topology != "patches")
                return err("a tessellated draw needs topology = \"patches\"", at("topology"));
            if (p.mesh.empty() && p.vertex_count <= 0 && p.indirect.empty())
                return err("a draw pass needs mesh = \"name\", vertex_count > 0 (vertices from gl_VertexIndex) or indirect", p.loc);
            break;
        case PassKind::compute:
            if (p.compute.empty()) return err("a compute pass needs compute = \"file.comp\"", p.loc);
            if (!p.groups.empty() && !p.threads.empty()) return err("give groups or threads, not both", at("threads"));
            if (p.groups.empty() && p.threads.empty() && p.indirect.empty())
                return err("a compute pass needs groups = ... (work groups) or threads = ... (invocations)", p.loc);
            break;
        case PassKind::blit:
        case PassKind::copy:
            if (p.src.empty() || p.dst.empty())
                return err("a " + std::string(kind_name(p.kind)) + " pass needs src = \"name\" and dst = \"name\"", p.loc);
            break;
        case PassKind::mips:
        case PassKind::clear:
            if (p.image.empty()) return err("a " + std::string(kind_name(p.kind)) + " pass needs image = \"name\"", p.loc);
            break;
        }
        return ok_status();
    }

    Status shaders() const {
        for (auto [ref, key] : {std::pair{&p.vertex, "vertex"}, {&p.fragment, "fragment"}, {&p.geometry, "geometry"},
                                {&p.tess_control, "tess_control"}, {&p.tess_eval, "tess_eval"}, {&p.compute, "compute"}}) {
            if (ref->empty() || !resolve_shader_path(ref->file, search).empty()) continue;
            Error e = err("the shader '" + ref->file + "' not found", ref->loc);
            e.notes.push_back(std::string("the ") + key + " shader of the pass");
            for (const auto& d : search) e.notes.push_back("looked in " + d.string());
            // A near miss among the files next to it ("blurr.frag" for "blur.frag").
            std::vector<std::string> candidates;
            std::error_code ec;
            for (const auto& d : search) {
                fs::path dir = (d / ref->file).parent_path();
                for (fs::directory_iterator it(dir, ec), end; !ec && it != end; it.increment(ec))
                    if (it->is_regular_file(ec))
                        candidates.push_back((fs::path(ref->file).parent_path() / it->path().filename()).generic_string());
            }
            std::string near = nearest_name(ref->file, candidates);
            if (!near.empty()) e.hint = "did you mean '" + near + "'?";
            return e;
        }
        return ok_status();
    }

    Status attachments() const {
        std::map<std::string, SourceLoc> used;  // by the image owning the memory
        auto use = [&](const ImageDesc* d, const std::string& as, const SourceLoc& l) -> Status {
            const ImageDesc* b = base(d);
            auto [it, fresh] = used.emplace(b->name, l);
            if (fresh) return ok_status();
            Error e = err("image '" + as + "' is attached twice" + (b->name != as ? " (it is an alias of '" + b->name + "')" : ""), l, as);
            e.notes.push_back("first attached at " + it->second.str());
            return e;
        };
        auto layer_ok = [&](const ImageDesc* d, const AttachmentRef& a) -> Status {
            const ImageDesc* b = base(d);
            if (b->kind == ImageKind::tex3d) return ok_status();  // slices: depth known only after evaluation
            int layers = b->kind == ImageKind::cube ? 6 : b->kind == ImageKind::tex2d_array ? b->layers : 1;
            if (a.layer >= layers || (a.layer < 0 && layers == 1))
                return err("image '" + a.image + "' has " + std::to_string(layers) + " layer" + (layers == 1 ? "" : "s") +
                               "; layer " + (a.layer == -1 ? "\"all\"" : a.layer == -2 ? "\"iteration\"" : std::to_string(a.layer)) +
                               " is not one of them",
                           a.loc, a.image);
            if (b->mips > 0 && a.mip >= b->mips)
                return err("image '" + a.image + "' has " + std::to_string(b->mips) + " mip" + (b->mips == 1 ? "" : "s") + "; mip " +
                               std::to_string(a.mip) + " does not exist",
                           a.loc, a.image);
            return ok_status();
        };
        for (const auto& t : p.targets) {
            if (auto s = need_image(t.image, t.loc); !s) return s;
            const ImageDesc* d = g.find_image(t.image);
            const vk::FormatInfo* f = format(d);
            if (f && f->is_depth)
                return err("'" + t.image + "' has a depth format (" + effective_format(g, *d) + "); attach it with depth = \"" + t.image + "\"",
                           t.loc, t.image);
            if (f && f->compressed())
                return err("'" + t.image + "' is block-compressed (" + effective_format(g, *d) +
                               "): sampled only; fill it with a copy pass from a buffer of blocks",
                           t.loc, t.image);
            if (!base(d)->file.empty() || !base(d)->generator.empty())
                return err("'" + t.image + "' comes from a " + std::string(base(d)->file.empty() ? "generator" : "file") +
                               "; render into an image of its own",
                           t.loc, t.image);
            if (auto s = use(d, t.image, t.loc); !s) return s;
            if (auto s = layer_ok(d, t); !s) return s;
            if (!t.resolve.empty()) {
                SourceLoc rl = t.resolve_loc.known() ? t.resolve_loc : t.loc;
                if (auto s = need_image(t.resolve, rl, "resolve image"); !s) return s;
                const ImageDesc* r = g.find_image(t.resolve);
                if (base(d)->samples == 1) return err("'" + t.image + "' is single-sampled; only a multisampled target resolves", t.loc, t.image);
                if (base(r)->samples != 1) return err("resolve image '" + t.resolve + "' must be single-sampled", rl, t.resolve);
                if (effective_format(g, *r) != effective_format(g, *d))
                    return err("resolve image '" + t.resolve + "' is " + effective_format(g, *r) + " but '" + t.image + "' is " +
                                   effective_format(g, *d) + "; a resolve needs the same format",
                               rl, t.resolve);
                if (auto s = use(r, t.resolve, rl); !s) return s;
            }
        }
        if (p.blend.size() > 1 && p.blend.size() != p.targets.size())
            return err("blend lists " + std::to_string(p.blend.size()) + " modes for " + std::to_string(p.targets.size()) +
                           " targets; give one for all or one per target",
                       at("blend"));
        if (p.depth) {
            const AttachmentRef& a = p.depth->target;
            if (auto s = need_image(a.image, a.loc, "depth image"); !s) return s;
            const ImageDesc* d = g.find_image(a.image);
            const vk::FormatInfo* f = format(d);
            if (f && !f->is_depth)
                return err("depth image '" + a.image + "' has the colour format " + effective_format(g, *d) + "; use d16, d32, d24s8 or d32s8",
                           a.loc, a.image);
            if (p.stencil.enable && f && !f->has_stencil)
                return err("stencil needs a depth image with stencil (d24s8 or d32s8); '" + a.image + "' is " + effective_format(g, *d),
                           at("stencil"), a.image);
            if (auto s = use(d, a.image, a.loc); !s) return s;
            if (auto s = layer_ok(d, a); !s) return s;
        } else if (p.stencil.enable) {
            return err("stencil needs a depth attachment with a stencil format: add depth = \"name\" (d24s8 or d32s8)", at("stencil"));
        }
        bool raster = p.kind == PassKind::fullscreen || p.kind == PassKind::draw;
        if (raster && p.targets.empty() && !p.depth) return err("the pass renders into nothing: add targets = [...] or depth", p.loc);
        if (raster && p.clear.color && p.targets.empty()) return err("clear.color but the pass has no colour targets", at("clear.color"));
        if (raster && p.clear.color)
            for (const auto& t : p.targets)  // one clear value for every target: each must take it exactly
                if (const vk::FormatInfo* f = format(g.find_image(t.image)))
                    if (std::string why = vk::clear_value_problem(*f, *p.clear.color); !why.empty())
                        return err("target '" + t.image + "': " + why, at("clear.color"), t.image);
        if (raster && (p.clear.depth || p.clear.stencil) && !p.depth)
            return err("clear.depth / clear.stencil but the pass has no depth attachment", at(p.clear.depth ? "clear.depth" : "clear.stencil"));
        return ok_status();
    }

    Status references() const {
        if (!p.mesh.empty() && !g.find_mesh(p.mesh)) return ref_error("mesh", p.mesh, at("mesh"), p.name, names.meshes, "meshes");
        if (!p.indirect.empty())
            if (auto s = need_buffer(p.indirect, at("indirect"), "indirect buffer"); !s) return s;
        switch (p.kind) {
        case PassKind::blit:
            if (auto s = need_image(p.src, at("src"), "src image"); !s) return s;
            if (auto s = need_image(p.dst, at("dst"), "dst image"); !s) return s;
            for (const std::string* n : {&p.src, &p.dst})
                if (const vk::FormatInfo* f = format(g.find_image(*n)); f && f->compressed())
                    return err("'" + *n + "' is block-compressed; blit cannot read or write it (sample it in a pass)",
                               at(n == &p.src ? "src" : "dst"), *n);
            break;
        case PassKind::copy: {
            // image -> image, buffer -> buffer, and buffer <-> image (texels, or the blocks of a
            // block-compressed image, tightly packed row by row).
            bool src_buffer = g.find_buffer(p.src), dst_buffer = g.find_buffer(p.dst);
            if (!src_buffer)
                if (auto s = need_image(p.src, at("src"), "src image or buffer"); !s) return s;
            if (!dst_buffer)
                if (auto s = need_image(p.dst, at("dst"), "dst image or buffer"); !s) return s;
            if (!src_buffer && !dst_buffer) {
                const vk::FormatInfo* fs = format(g.find_image(p.src));
                const vk::FormatInfo* fd = format(g.find_image(p.dst));
                if ((fs && fs->compressed()) || (fd && fd->compressed()))
                    return err("a block-compressed image is filled from a buffer of blocks: copy from a buffer", at("dst"));
            }
            // The image side of a buffer <-> image copy: single-sampled colour only.
            if (src_buffer != dst_buffer) {
                const std::string& n = src_buffer ? p.dst : p.src;
                const char* key = src_buffer ? "dst" : "src";
                const ImageDesc* d = g.find_image(n);
                if (base(d)->samples > 1) return err("a multisampled image cannot be copied to or from a buffer", at(key), n);
                const vk::FormatInfo* f = format(d);
                if (f && f->is_depth) return err("a depth image cannot be copied to or from a buffer here", at(key), n);
            }
            break;
        }
        case PassKind::mips: {
            if (auto s = need_image(p.image, at("image")); !s) return s;
            const ImageDesc* b = base(g.find_image(p.image));
            if (b->mips == 1) return err("image '" + p.image + "' has one mip; declare it with mips = \"full\" or mips = N", at("image"), p.image);
            if (const vk::FormatInfo* f = format(b); f && f->compressed())
                return err("image '" + p.image + "' is block-compressed; mips cannot be generated for it", at("image"), p.image);
            break;
        }
        case PassKind::clear:
            if (g.find_buffer(p.image)) {
                if (p.clear.color)
                    if (std::string why = vk::fill_value_problem((*p.clear.color)[0]); !why.empty())
                        return err("buffer '" + p.image + "': " + why, at("clear.color"), p.image);
            } else {
                if (auto s = need_image(p.image, at("image"), "image or buffer"); !s) return s;
                const vk::FormatInfo* f = format(g.find_image(p.image));
                if (f && f->compressed())
                    return err("image '" + p.image + "' is block-compressed and cannot be cleared", at("image"), p.image);
                if (f && !f->is_depth && p.clear.color)
                    if (std::string why = vk::clear_value_problem(*f, *p.clear.color); !why.empty())
                        return err("image '" + p.image + "': " + why, at("clear.color"), p.image);
            }
            break;
        default: break;
        }
        if (!p.src.empty() && p.src == p.dst) return err("src and dst are the same; copy between two resources", at("dst"));
        for (size_t k = 0; k < p.swap.size(); ++k) {
            if (!g.find_image(p.swap[k])) return ref_error("swap image", p.swap[k], p.swap_loc, p.name, names.images, "images");
            if (k % 2 && p.swap[k] == p.swap[k - 1]) return err("swap pairs an image with itself", p.swap_loc, p.swap[k]);
        }
        if (!p.swap.empty() && p.repeat.empty()) return err("swap exchanges images between iterations; add repeat = N", p.swap_loc);
        for (const auto& [shader_name, res] : p.bind)
            if (!g.find_image(res) && !g.find_buffer(res) && !is_previous_frame(res))
                return ref_error("bind target", res, p.keys.at("bind." + shader_name, p.bind_loc), p.name, names.resources(), "images and buffers");
        for (const auto& [shader_name, v] : p.bind_views)
            if (auto s = need_image(v.image, p.keys.at("bind." + shader_name, p.bind_loc), "a view's image (mip/layer)"); !s) return s;
        return ok_status();
    }
};

} // namespace

Status validate_passes(const GraphDesc& g, const ValidateOptions& opt, const DeclaredNames& names) {
    std::vector<fs::path> search = opt.search_dirs.empty() ? default_search_dirs(g) : opt.search_dirs;
    std::set<std::string> seen;
    for (const auto& p : g.passes) {
        if (!seen.insert(p.name).second) {
            Error e = make_error("a pass named '" + p.name + "' already exists", p.loc);
            e.pass = p.name;
            return e;
        }
        PassChecker c{g, names, p, search};
        if (auto s = c.kind_and_keys(); !s) return s;
        if (auto s = c.shaders(); !s) return s;
        if (auto s = c.attachments(); !s) return s;
        if (auto s = c.references(); !s) return s;
    }
    return ok_status();
}

} // namespace pl::graph
