// What a test's check refers to: the images of `pass`, `other` and `mask`, the buffer of
// `buffer`, the param of `param`, each reported at its value with a "did you mean". Keys and
// their types were checked by parse_checks.cpp. What a test reads (levels, layers, pixels, buffer
// elements) is checked at the test's own size by validate_test_reads.
#include "graph/readable.hpp"
#include "graph/validate_parts.hpp"

namespace pl::graph {

namespace {

const std::string* string_arg(const CheckDesc& c, const char* key) {
    auto it = c.args.find(key);
    return it == c.args.end() ? nullptr : std::get_if<std::string>(&it->second);
}

const double* number_arg(const CheckDesc& c, const char* key) {
    auto it = c.args.find(key);
    return it == c.args.end() ? nullptr : std::get_if<double>(&it->second);
}

std::string count_text(int64_t n, const char* what) {
    return std::to_string(n) + " " + what + (n == 1 ? "" : "s") + (n > 0 ? " (0.." + std::to_string(n - 1) + ")" : "");
}

// Level `mip`, layer `layer` and (when given) texel `px` of image `name` exist at `env`.
// Sizes the validation cannot know (file images) are left to the run.
Status image_read(const GraphDesc& g, const std::string& name, int mip, int layer, const std::vector<double>* px, const SizeEnv& env,
                  const SourceLoc& mip_loc, const SourceLoc& layer_loc, const SourceLoc& px_loc, const std::string& owner) {
    const ImageDesc* d = g.find_image(name);
    if (!d) return ok_status();  // reported by the name checks
    auto fail = [&](const std::string& msg, const SourceLoc& l) {
        Error e = make_error(owner + ": image '" + name + "' " + msg, l);
        e.resource = name;
        return e;
    };
    int levels = image_levels(g, *d, env);
    if (levels > 0 && mip >= levels) return fail("has " + count_text(levels, "mip") + "; mip " + std::to_string(mip) + " does not exist", mip_loc);
    auto ext = image_extent(g, *d, env);
    bool is3d = d->kind == ImageKind::tex3d;
    if (is3d && !ext) return ok_status();
    int layers = is3d ? static_cast<int>(std::max<int64_t>(1, ext->d >> mip)) : image_layers(g, *d);
    if (layer >= layers)
        return fail("has " + count_text(layers, is3d ? "slice" : "layer") + (is3d && mip ? " at mip " + std::to_string(mip) : "") + "; layer " +
                        std::to_string(layer) + " does not exist",
                    layer_loc);
    if (!px || px->size() != 2 || !ext) return ok_status();
    int64_t w = std::max<int64_t>(1, ext->w >> mip), h = std::max<int64_t>(1, ext->h >> mip);
    if ((*px)[0] >= double(w) || (*px)[1] >= double(h))
        return fail("is " + std::to_string(w) + "x" + std::to_string(h) + (mip ? " at mip " + std::to_string(mip) : "") + " in this test; px = [" +
                        std::to_string(int64_t((*px)[0])) + ", " + std::to_string(int64_t((*px)[1])) + "] is outside it",
                    px_loc);
    return ok_status();
}

// The elements a buffer check selects lie inside the buffer's size at `env` (host-built buffers
// are sized by their build: left to the run).
Status buffer_read(const GraphDesc& g, const CheckDesc& c, const std::string& name, const SizeEnv& env, const std::string& owner) {
    const BufferDesc* b = g.find_buffer(name);
    if (!b || !b->generator.empty()) return ok_status();
    auto bytes = eval_scalar(b->size, env);
    if (!bytes || *bytes < 0) return ok_status();  // reported by size validation
    size_t size = (static_cast<size_t>(*bytes) + 3) / 4 * 4;
    const double* stride_v = number_arg(c, "stride");
    const double* field_v = number_arg(c, "field");
    size_t stride = stride_v ? static_cast<size_t>(*stride_v) : 4, field = field_v ? static_cast<size_t>(*field_v) : 0;
    size_t elements = buffer_elements(size, stride, field);
    size_t first = 0, count = elements;
    SourceLoc loc = c.loc;
    const char* key = nullptr;
    if (const double* index = number_arg(c, "index")) first = static_cast<size_t>(*index), count = 1, key = "index";
    else if (auto it = c.args.find("range"); it != c.args.end())
        if (const auto* r = std::get_if<std::vector<double>>(&it->second); r && r->size() == 2)
            first = static_cast<size_t>((*r)[0]), count = static_cast<size_t>((*r)[1]), key = "range";
    if (key) loc = c.keys.at(key, c.loc);
    if (count > 0 && first + count <= elements) return ok_status();
    // The run's wording (check::select), located at the selection.
    std::string label = "buffer '" + name + "'";
    if (count > 0) label += "[" + std::to_string(first) + (count == 1 ? "" : ".." + std::to_string(first + count - 1)) + "]";
    if (stride != 4 || field) label += " field " + std::to_string(field) + " (stride " + std::to_string(stride) + ")";
    Error e = make_error(owner + ": " + label + " is outside the buffer: " + std::to_string(size) + " bytes hold " + std::to_string(elements) +
                             " element(s) of " + std::to_string(stride) + " bytes",
                         loc);
    e.resource = name;
    if (!b->size.text.empty())
        e.notes.push_back("size = \"" + b->size.text + "\" evaluated at " + std::to_string(env.view_w) + "x" + std::to_string(env.view_h));
    return e;
}

} // namespace

Status validate_test_reads(const GraphDesc& g, const TestDesc& t, const SizeEnv& env) {
    std::string subject = !t.pass.empty() ? t.pass : !g.output.empty() ? g.output : default_output(g);
    std::string owner = "test '" + t.name + "'";
    if (auto s = image_read(g, subject, t.mip, t.layer, nullptr, env, t.keys.at("mip", t.loc), t.keys.at("layer", t.loc), t.loc, owner); !s)
        return s;
    for (const auto& c : t.checks) {
        std::string what = owner + ": " + c.kind;
        if (const std::string* name = string_arg(c, "buffer")) {
            if (auto s = buffer_read(g, c, *name, env, what); !s) return s;
            continue;
        }
        const std::string* pass = string_arg(c, "pass");
        std::string which = pass ? *pass : subject;
        bool own = which == subject;  // the case's own image defaults to the case's level and layer
        const double* mip = number_arg(c, "mip");
        const double* layer = number_arg(c, "layer");
        const std::vector<double>* px = nullptr;
        if (auto it = c.args.find("px"); it != c.args.end()) px = std::get_if<std::vector<double>>(&it->second);
        SourceLoc own_mip = mip ? c.keys.at("mip", c.loc) : own ? t.keys.at("mip", c.loc) : c.loc;
        SourceLoc own_layer = layer ? c.keys.at("layer", c.loc) : own ? t.keys.at("layer", c.loc) : c.loc;
        if (auto s = image_read(g, which, mip ? int(*mip) : own ? t.mip : 0, layer ? int(*layer) : own ? t.layer : 0, px, env, own_mip, own_layer,
                                c.keys.at("px", c.loc), what);
            !s)
            return s;
    }
    return ok_status();
}

Status validate_check(const GraphDesc& g, const DeclaredNames& n, const TestDesc& t, const CheckDesc& c, const SizeEnv& env) {
    auto located = [&](Error e) {
        e.message = "test '" + t.name + "': " + c.kind + ": " + e.message;
        return e;
    };
    for (const char* key : {"pass", "other", "mask", "of"}) {
        const std::string* name = string_arg(c, key);
        if (!name || g.find_image(*name)) continue;
        Error e = ref_error("image", *name, c.keys.at(key, c.loc), "", n.images, "images");
        if (g.find_buffer(*name)) e.hint = "'" + *name + "' is a buffer: check it with buffer = \"" + *name + "\"";
        return located(e);
    }
    if (const std::string* name = string_arg(c, "buffer"); name && !g.find_buffer(*name)) {
        Error e = ref_error("buffer", *name, c.keys.at("buffer", c.loc), "", n.buffers, "buffers");
        if (g.find_image(*name)) e.hint = "'" + *name + "' is an image: check it with pass = \"" + *name + "\"";
        return located(e);
    }
    if (const std::string* name = string_arg(c, "param"); name && !g.find_param(*name))
        return located(ref_error("param", *name, c.keys.at("param", c.loc), "", n.params, "params"));
    // expect = "view.w*view.h" (buffer checks): an expression of the view and params.
    if (const std::string* text = string_arg(c, "expect")) {
        auto v = eval_scalar(SizeExpr{*text, {}, c.keys.at("expect", c.loc)}, env);
        if (!v) return located(v.error());
    }
    return ok_status();
}

} // namespace pl::graph
