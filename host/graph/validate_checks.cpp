// What a test's check refers to: the images of `pass`, `other` and `mask`, the buffer of
// `buffer`, the param of `param`, each reported at its value with a "did you mean". Keys and
// their types were checked by parse_checks.cpp.
#include "graph/validate_parts.hpp"

namespace pl::graph {

namespace {

const std::string* string_arg(const CheckDesc& c, const char* key) {
    auto it = c.args.find(key);
    return it == c.args.end() ? nullptr : std::get_if<std::string>(&it->second);
}

} // namespace

Status validate_check(const GraphDesc& g, const DeclaredNames& n, const TestDesc& t, const CheckDesc& c, const SizeEnv& env) {
    auto located = [&](Error e) {
        e.message = "test '" + t.name + "': " + c.kind + ": " + e.message;
        return e;
    };
    for (const char* key : {"pass", "other", "mask"}) {
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
