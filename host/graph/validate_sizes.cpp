// Sizes are evaluated and bounded before anything is allocated: a typo such as "view*100" must
// be an error at its TOML line, not a driver out-of-memory or a machine that swaps.
#include "graph/validate_parts.hpp"

#include "vk/formats.hpp"

namespace pl::graph {

namespace {

// Large enough for any course technique, small enough that a typo cannot exhaust the machine.
constexpr int64_t kMaxSide = 16384, kMax3DSide = 2048;
constexpr int64_t kMaxImageBytes = int64_t(2) << 30, kMaxBufferBytes = int64_t(1) << 30;
constexpr int64_t kMaxGroups = 65535;  // Vulkan's guaranteed maxComputeWorkGroupCount per axis
constexpr int64_t kMaxRepeat = 4096;

struct Ctx {
    const std::string& context;
    const SourceLoc& context_loc;
    Error with(Error e) const {
        if (!context.empty()) e.notes.push_back(context + (context_loc.known() ? " at " + context_loc.str() : ""));
        return e;
    }
};

std::string extent_text(const Extent& x, int dims) {
    return std::to_string(x.w) + "x" + std::to_string(x.h) + (dims == 3 ? "x" + std::to_string(x.d) : "");
}

Status image_size(const GraphDesc& g, const ImageDesc& i, const SizeEnv& env, const Ctx& c) {
    auto err = [&](const std::string& msg, const SourceLoc& l) {
        Error e = make_error("image '" + i.name + "': " + msg, l.known() ? l : i.loc);
        e.resource = i.name;
        return c.with(std::move(e));
    };
    if (!i.alias.empty() || !i.file.empty()) return ok_status();  // sized by the target / the file
    SizeExpr size = i.size;
    if (size.empty()) {
        if (i.generator.empty()) size.text = "view";
        else size.literal = {256, 256};
        size.loc = i.loc;
    }
    int dims = i.kind == ImageKind::tex3d ? 3 : 2;
    auto ext = eval_extent(size, env, dims);
    if (!ext) {
        Error e = ext.error();
        e.resource = i.name;
        if (e.message.rfind("image '", 0) != 0) e.message = "image '" + i.name + "': " + e.message;
        return c.with(std::move(e));
    }
    int64_t limit = dims == 3 ? kMax3DSide : kMaxSide;
    std::string text = extent_text(*ext, dims);
    if (ext->w < 1 || ext->h < 1 || ext->d < 1)
        return err("size evaluates to " + text + "; every side must be at least 1", size.loc);
    if (ext->w > limit || ext->h > limit || ext->d > limit)
        return err("size evaluates to " + text + "; sides are limited to " + std::to_string(limit) + (dims == 3 ? " for 3D images" : ""),
                   size.loc);
    if (i.kind == ImageKind::cube && ext->w != ext->h) return err("a cube image must be square, not " + text, size.loc);
    const vk::FormatInfo* f = vk::find_format(effective_format(g, i));
    double texel = f ? double(f->bytes_per_texel) / (f->block * f->block) : 16;
    double layers = i.kind == ImageKind::cube ? 6 : i.kind == ImageKind::tex2d_array ? std::max(1, i.layers) : 1;
    // A full mip chain adds a third in 2D (1/4 + 1/16 + ...) and a seventh in 3D.
    double chain = i.mips == 1 ? 1.0 : dims == 3 ? 8.0 / 7.0 : 4.0 / 3.0;
    double bytes = double(ext->w) * double(ext->h) * double(ext->d) * layers * texel * i.samples * (i.history ? 2 : 1) * chain;
    if (bytes > double(kMaxImageBytes)) {
        Error e = err("would need " + human_bytes(bytes) + " (limit " + human_bytes(double(kMaxImageBytes)) + ")", size.loc);
        e.notes.insert(e.notes.begin(), text + " x " + (texel == double(int(texel)) ? std::to_string(int(texel)) : std::to_string(texel).substr(0, 3)) + " bytes per texel" +
                                            (layers > 1 ? " x " + std::to_string(int(layers)) + " layers" : "") +
                                            (i.samples > 1 ? " x " + std::to_string(i.samples) + " samples" : "") +
                                            (i.history ? " x 2 (history)" : "") + (chain > 1 ? " + mips" : ""));
        return e;
    }
    return ok_status();
}

Status buffer_size(const BufferDesc& b, const SizeEnv& env, const Ctx& c) {
    if (!b.generator.empty()) return ok_status();  // sized by its build (bounded when it is built)
    auto sz = eval_scalar(b.size, env);
    if (!sz) {
        Error e = sz.error();
        e.resource = b.name;
        if (e.message.rfind("buffer '", 0) != 0) e.message = "buffer '" + b.name + "': " + e.message;
        return c.with(std::move(e));
    }
    if (*sz < 4 || *sz > kMaxBufferBytes) {
        Error e = make_error("buffer '" + b.name + "': size evaluates to " + std::to_string(*sz) + " bytes; it must be between 4 bytes and " +
                                 human_bytes(double(kMaxBufferBytes)),
                             b.size.loc.known() ? b.size.loc : b.loc);
        e.resource = b.name;
        return c.with(std::move(e));
    }
    if (!b.data.empty() && int64_t(b.data.size()) * 4 > *sz) {
        Error e = make_error("buffer '" + b.name + "': data holds " + std::to_string(b.data.size() * 4) + " bytes but the buffer has " +
                                 std::to_string(*sz),
                             b.keys.at("data", b.loc));
        e.resource = b.name;
        return c.with(std::move(e));
    }
    return ok_status();
}

// A counter word must lie inside its buffer, and its capacity must evaluate to a count >= 0.
Status counter_size(const BufferDesc& b, const SizeEnv& env, const Ctx& c) {
    if (!b.counter) return ok_status();
    auto fail = [&](const std::string& msg, const SourceLoc& l) {
        Error e = make_error("buffer '" + b.name + "': " + msg, l.known() ? l : b.counter->loc);
        e.resource = b.name;
        return c.with(std::move(e));
    };
    auto sz = eval_scalar(b.size, env);
    if (sz && int64_t(b.counter->offset) + 4 > *sz)
        return fail("counter offset " + std::to_string(b.counter->offset) + " is outside the buffer's " + std::to_string(*sz) + " bytes",
                    b.keys.at("counter.offset", b.counter->loc));
    auto cap = eval_scalar(b.counter->capacity, env);
    if (!cap) {
        Error e = cap.error();
        e.resource = b.name;
        return c.with(std::move(e));
    }
    if (*cap < 0 || *cap > int64_t(UINT32_MAX))
        return fail("counter capacity evaluates to " + std::to_string(*cap) + "; it must be between 0 and 4294967295",
                    b.counter->capacity.loc);
    return ok_status();
}

Status pass_sizes(const PassDesc& p, const SizeEnv& env, const Ctx& c) {
    auto err = [&](const std::string& msg, const SourceLoc& l) {
        Error e = make_error(msg, l.known() ? l : p.loc);
        e.pass = p.name;
        return c.with(std::move(e));
    };
    auto located = [&](Error e) {
        e.pass = p.name;
        return c.with(std::move(e));
    };
    for (auto [key, expr] : {std::pair{"groups", &p.groups}, {"threads", &p.threads}}) {
        if (expr->empty()) continue;
        auto v = eval_size(*expr, env);
        if (!v) return located(v.error());
        std::string text;
        for (int64_t x : *v) text += (text.empty() ? "" : "x") + std::to_string(x);
        for (int64_t x : *v) {
            if (x < 1) return err(std::string(key) + " evaluates to " + text + "; every component must be at least 1", expr->loc);
            int64_t limit = std::string(key) == "groups" ? kMaxGroups : kMaxGroups * 1024;
            if (x > limit) return err(std::string(key) + " evaluates to " + text + "; components are limited to " + std::to_string(limit), expr->loc);
        }
    }
    if (!p.repeat.empty()) {
        auto r = eval_scalar(p.repeat, env);
        if (!r) return located(r.error());
        if (*r < 1 || *r > kMaxRepeat)
            return err("repeat evaluates to " + std::to_string(*r) + "; it must be between 1 and " + std::to_string(kMaxRepeat), p.repeat.loc);
    }
    return ok_status();
}

} // namespace

Status check_built_buffer_size(const BufferDesc& b, int64_t bytes) {
    if (bytes <= kMaxBufferBytes) return ok_status();
    Error e = make_error("buffer '" + b.name + "': the " + b.generator + " build needs " + std::to_string(bytes) + " bytes (limit " +
                             human_bytes(double(kMaxBufferBytes)) + ")",
                         b.keys.at("generator", b.loc));
    e.resource = b.name;
    return e;
}

Status validate_sizes(const GraphDesc& g, const SizeEnv& env, const std::string& context, const SourceLoc& context_loc) {
    Ctx c{context, context_loc};
    for (const auto& i : g.images)
        if (auto s = image_size(g, i, env, c); !s) return s;
    for (const auto& b : g.buffers)
        if (auto s = buffer_size(b, env, c); !s) return s;
    for (const auto& b : g.buffers)
        if (auto s = counter_size(b, env, c); !s) return s;
    for (const auto& p : g.passes)
        if (auto s = pass_sizes(p, env, c); !s) return s;
    for (const auto& gr : g.groups) {
        if (gr.repeat.empty()) continue;
        auto r = eval_scalar(gr.repeat, env);
        if (!r) return c.with(r.error());
        if (*r < 1 || *r > kMaxRepeat)
            return c.with(make_error("group '" + gr.name + "': repeat evaluates to " + std::to_string(*r) + "; it must be between 1 and " +
                                         std::to_string(kMaxRepeat),
                                     gr.repeat.loc.known() ? gr.repeat.loc : gr.loc));
    }
    return ok_status();
}

} // namespace pl::graph
