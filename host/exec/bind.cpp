#include "exec/bind.hpp"

#include "graph/camera_values.hpp"
#include "shader/include.hpp"
#include "util/scan.hpp"
#include "vk/formats.hpp"

#include <algorithm>
#include <fstream>

namespace fs = std::filesystem;

namespace pl::exec {

using graph::ImageKind;
using shader::BindingType;

graph::SizeEnv size_env(const graph::GraphDesc& desc, std::array<int, 2> view) { return graph::make_env(desc, view); }

namespace {

// `line` with its comments blanked (columns kept); `in_block` carries a /* comment across lines.
std::string code_of(const std::string& line, bool& in_block) {
    std::string out = line;
    for (size_t i = 0; i < out.size(); ++i) {
        if (in_block) {
            if (out.compare(i, 2, "*/") == 0) in_block = false, out[i] = out[i + 1] = ' ', ++i;
            else out[i] = ' ';
        } else if (out.compare(i, 2, "//") == 0) {
            std::fill(out.begin() + static_cast<long>(i), out.end(), ' ');
            break;
        } else if (out.compare(i, 2, "/*") == 0) {
            in_block = true, out[i] = out[i + 1] = ' ', ++i;
        }
    }
    return out;
}

} // namespace

SourceLoc find_declaration(const std::vector<fs::path>& files, const std::vector<std::string>& names) {
    for (const auto& name : names) {
        if (name.empty()) continue;
        for (const auto& f : files) {
            std::ifstream in(f);
            std::string raw;
            bool in_block = false;
            for (int n = 1; std::getline(in, raw); ++n) {
                // Only code counts: a comment that says "the scene buffer" is not a declaration.
                std::string line = code_of(raw, in_block);
                if (line.find("uniform") == std::string::npos && line.find("buffer") == std::string::npos) continue;
                if (size_t at = scan::find_word(line, name); at != std::string::npos)
                    return {shader::display_path(f), n, static_cast<int>(at) + 1};
            }
        }
    }
    return {};
}

namespace {

std::string underlying(const graph::GraphDesc& d, const std::string& name) {
    const graph::ImageDesc* img = d.find_image(name);
    return img && !img->alias.empty() ? img->alias : name;
}

Access storage_access(const shader::Binding& b) {
    if (b.non_writable) return Access::storage_read;
    if (b.non_readable) return Access::storage_write;
    return Access::storage_read_write;
}

// Does a sampler/image declaration of this dimension fit the image's kind?
bool dim_matches(const shader::Binding& b, const graph::ImageDesc& img) {
    switch (b.dim) {
    case shader::ImageDim::cube: return img.kind == ImageKind::cube;
    case shader::ImageDim::d3: return img.kind == ImageKind::tex3d;
    case shader::ImageDim::d2:
        if (b.arrayed) return img.kind == ImageKind::tex2d_array || img.kind == ImageKind::cube;
        return img.kind == ImageKind::tex2d || (img.kind == ImageKind::tex2d_array && img.layers == 1);
    default: return true;
    }
}

const char* kind_name(ImageKind k) {
    switch (k) {
    case ImageKind::tex2d: return "2d";
    case ImageKind::tex2d_array: return "2d-array";
    case ImageKind::tex3d: return "3d";
    case ImageKind::cube: return "cube";
    }
    return "?";
}

} // namespace

Status bind_pass(const graph::GraphDesc& desc, CompiledPass& cp) {
    const graph::PassDesc& pd = *cp.desc;
    // Located at the shader's declaration: the graph name, else the shader's instance or block
    // name (`} scene;` of `buffer PlScene {` is on a line of its own).
    auto err = [&](const std::string& msg, const std::string& name, const shader::Binding* b = nullptr) {
        Error e = make_error(msg, find_declaration(cp.program.dependencies, {name, b ? b->name : "", b ? b->block_name : ""}));
        if (!e.loc.known()) e.loc = pd.loc, e.source_line = read_source_line(pd.loc.file, pd.loc.line);
        e.pass = pd.name;
        e.resource = name;
        return e;
    };
    std::vector<std::string> reads, writes;

    for (const auto& b : cp.program.reflection.bindings) {
        BoundResource br;
        br.binding = b;
        if (b.block_name == "PasslabFrame") {
            br.kind = BoundResource::Kind::frame;
            br.access = Access::uniform_read;
            cp.bindings.push_back(br);
            continue;
        }
        if (b.block_name == "PasslabCameras") {
            br.kind = BoundResource::Kind::cameras;
            br.access = Access::uniform_read;
            cp.bindings.push_back(br);
            continue;
        }
        if (b.block_name == "PasslabParams") {
            br.kind = BoundResource::Kind::params;
            br.access = Access::uniform_read;
            cp.bindings.push_back(br);
            continue;
        }
        bool is_buffer = b.type == BindingType::uniform_buffer || b.type == BindingType::storage_buffer;
        std::string name = b.name;
        if (auto it = pd.bind.find(name); it != pd.bind.end()) name = it->second;
        else if (auto bt = pd.bind.find(b.block_name); is_buffer && bt != pd.bind.end()) name = bt->second;
        if (is_buffer && !desc.find_buffer(name) && !b.block_name.empty() && desc.find_buffer(b.block_name))
            name = b.block_name;

        // One graph resource per binding: `uniform sampler2D x[2]` or a `buffer B { } b[2]` would
        // need N resources bound to one name, which the graph cannot say; refuse it here, at the
        // declaration, so `passlab check` catches it (not the first frame, at the pass's line).
        if (b.count != 1)
            return err("'" + b.name + "' is an array of " + (b.count ? std::to_string(b.count) : std::string("unsized")) +
                           " resources; arrays of samplers, images or buffers are not supported: declare one per graph "
                           "resource (" + (is_buffer ? std::string("one buffer block per buffer") : "e.g. `uniform sampler2D " + b.name + "0, " + b.name + "1;`") + ")",
                       name, &b);
        if (b.type == BindingType::sampler) return err("separate 'sampler' objects are not supported; declare a combined sampler (sampler2D ...) named after the image", name);

        // History: <name>_prev reads last frame's contents of a history image or buffer.
        bool prev = false;
        if (name.size() > 5 && name.ends_with("_prev")) {
            std::string base = name.substr(0, name.size() - 5);
            const graph::ImageDesc* hi = desc.find_image(base);
            // An alias of a history image reads the previous frame through its own sampler.
            if (hi && !hi->alias.empty()) hi = desc.find_image(hi->alias);
            const graph::BufferDesc* hb = desc.find_buffer(base);
            if ((hi && hi->history) || (hb && hb->history)) {
                prev = true;
                name = base;
            }
        }

        if (is_buffer) {
            const graph::BufferDesc* buf = desc.find_buffer(name);
            if (!buf) {
                std::vector<std::string> names;
                for (const auto& x : desc.buffers) names.push_back(x.name);
                Error e = err("shader block '" + name + "' is not a buffer of the graph", name, &b);
                suggest(e, name, names, "buffers", "the graph declares no [buffers]");
                if (e.hint.empty())
                    e.hint = "declare [buffers] " + name + " = { ... }" + (names.empty() ? "" : ", or bind the block to one: bind = { " + b.name + " = \"" + names[0] + "\" }");
                return e;
            }
            br.kind = prev ? BoundResource::Kind::buffer_prev : BoundResource::Kind::buffer;
            br.resource = name;
            br.access = b.type == BindingType::uniform_buffer ? Access::uniform_read : storage_access(b);
            if (prev && br.access != Access::uniform_read && br.access != Access::storage_read)
                br.access = Access::storage_read;
        } else {
            const graph::ImageDesc* img = desc.find_image(name);
            if (!img) {
                std::vector<std::string> names;
                for (const auto& x : desc.images) {
                    names.push_back(x.name);
                    if (x.history) names.push_back(x.name + "_prev");
                }
                Error e = err("shader resource '" + name + "' is not an image of the graph", name);
                suggest(e, name, names, "images", "the graph declares no [images]");
                return e;
            }
            // An alias has only its own sampler: kind, format and layers are its target's.
            if (!img->alias.empty())
                if (const graph::ImageDesc* target = desc.find_image(img->alias)) img = target;
            const vk::FormatInfo* fi = vk::find_format(img->format);
            if (auto v = pd.bind_views.find(b.name); v != pd.bind_views.end()) br.view = &v->second;
            // A view of one layer is a plain 2D image to the shader (sampler2D, image2D).
            const bool one_layer = br.view && !br.view->layer.empty() && img->kind != ImageKind::tex3d;
            if (one_layer && (b.dim != shader::ImageDim::d2 || b.arrayed))
                return err("'" + name + "' is bound to one layer of image '" + img->name +
                               "' (bind view with layer): declare it as a 2D sampler/image, not an array or cube", name);
            if (!one_layer && !dim_matches(b, *img))
                return err("'" + name + "' is a " + kind_name(img->kind) +
                               " image but the shader declares a different dimension", name);
            if (fi && b.is_integer != fi->is_integer)
                return err(std::string("'") + name + "' has format " + img->format + " but the shader declares " +
                               (b.is_integer ? "an integer" : "a float") + " sampler/image", name);
            br.kind = prev ? BoundResource::Kind::image_prev : BoundResource::Kind::image;
            br.resource = name;
            if (b.type == BindingType::storage_image) {
                if (!fi || std::string(fi->glsl_storage).empty())
                    return err("image '" + name + "' has format " + img->format +
                                   ", which cannot be a storage image", name);
                if (!b.storage_format.empty() && b.storage_format != fi->glsl_storage) {
                    Error e = err("storage image '" + name + "' is declared " + b.storage_format +
                                      " in the shader but the image's format is " + img->format, name);
                    e.hint = std::string("declare it layout(") + fi->glsl_storage + ")";
                    return e;
                }
                br.access = prev ? Access::storage_read : storage_access(b);
            } else {
                br.access = Access::sampled;
            }
        }

        std::string res = underlying(desc, br.resource) + (prev ? "_prev" : "");
        bool w = br.access == Access::storage_write || br.access == Access::storage_read_write;
        bool r = br.access != Access::storage_write;
        if (r) reads.push_back(res);
        if (w) writes.push_back(res);
        cp.bindings.push_back(br);
    }

    // Attachments and transfer operands declared in the graph.
    for (const auto& t : pd.targets) {
        writes.push_back(underlying(desc, t.image));
        if (!t.resolve.empty()) writes.push_back(underlying(desc, t.resolve));
    }
    if (pd.depth) {
        // The attachment is written by depth writes, by stencil ops that change the stencil
        // (a mirror or shadow-volume mark pass tests depth read-only but writes stencil) and
        // by a clear; otherwise the pass only reads it.
        auto changes = [](const graph::StencilFaceDesc& f) {
            return f.fail != "keep" || f.pass != "keep" || f.depth_fail != "keep";
        };
        bool stencil_writes = pd.stencil.enable && pd.stencil.write_mask != 0 &&
                              (changes(pd.stencil.front) || changes(pd.stencil.back));
        bool clears = pd.clear.depth.has_value() || pd.clear.stencil.has_value();
        if (pd.depth->write || stencil_writes || clears) writes.push_back(underlying(desc, pd.depth->target.image));
        else reads.push_back(underlying(desc, pd.depth->target.image));
    }
    if (!pd.src.empty()) reads.push_back(underlying(desc, pd.src));
    if (!pd.dst.empty()) writes.push_back(underlying(desc, pd.dst));
    if (!pd.image.empty()) {
        // mips reads level 0 and writes the rest; clear only writes.
        if (pd.kind == graph::PassKind::mips) reads.push_back(underlying(desc, pd.image));
        writes.push_back(underlying(desc, pd.image));
    }
    if (!pd.indirect.empty()) reads.push_back(pd.indirect);
    // Ping-pong partners trade roles every iteration: the pass reads and writes both.
    for (const auto& n : pd.swap) {
        reads.push_back(underlying(desc, n));
        writes.push_back(underlying(desc, n));
    }
    if (!pd.mesh.empty()) {}  // meshes are immutable host data: no ordering constraint

    // Feedback loop: sampling an image while rendering into it is undefined behaviour.
    auto sampled = [&](const std::string& n) {
        return std::any_of(cp.bindings.begin(), cp.bindings.end(), [&](const BoundResource& br) {
            // A binding of one level is checked per iteration against the levels rendered
            // (exec/views.cpp): reading level i while rendering level i + 1 is legal.
            return br.kind == BoundResource::Kind::image && br.access == Access::sampled && !br.view &&
                   underlying(desc, br.resource) == underlying(desc, n);
        });
    };
    for (const auto& t : pd.targets)
        if (sampled(t.image))
            return err("pass samples image '" + t.image + "' while rendering into it (feedback loop)", t.image);
    if (pd.depth && pd.depth->write && sampled(pd.depth->target.image))
        return err("pass samples depth image '" + pd.depth->target.image +
                       "' while writing it; set depth.write = false to test and sample it", pd.depth->target.image);

    auto uniq = [](std::vector<std::string>& v) {
        std::vector<std::string> out;
        for (auto& s : v)
            if (std::find(out.begin(), out.end(), s) == out.end()) out.push_back(s);
        v = std::move(out);
    };
    uniq(reads);
    uniq(writes);
    cp.io.reads = reads;
    cp.io.writes = writes;
    return ok_status();
}

} // namespace pl::exec
