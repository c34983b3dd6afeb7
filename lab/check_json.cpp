#include "check_json.hpp"

#include "exec/bind.hpp"
#include "graph/sizeexpr.hpp"

#include <nlohmann/json.hpp>

using json = nlohmann::ordered_json;

namespace pl::lab {

using graph::ParamType;

const char* widget_kind(const graph::ParamDesc& p) {
    const bool ranged = p.min && p.max && *p.min < *p.max;
    switch (p.type) {
    case ParamType::boolean: return "checkbox";
    case ParamType::enumeration: return "combo";
    case ParamType::i32: return ranged ? "slider_int" : "drag_int";
    case ParamType::color3:
    case ParamType::color4: return "color";
    default: return ranged ? (p.log ? "slider_log" : "slider") : "drag";
    }
}

namespace {

const char* param_type(ParamType t) {
    switch (t) {
    case ParamType::f32: return "float";
    case ParamType::i32: return "int";
    case ParamType::boolean: return "bool";
    case ParamType::vec2: return "vec2";
    case ParamType::vec3: return "vec3";
    case ParamType::vec4: return "vec4";
    case ParamType::color3: return "color3";
    case ParamType::color4: return "color4";
    case ParamType::enumeration: return "enum";
    }
    return "?";
}

const char* image_kind(graph::ImageKind k) {
    switch (k) {
    case graph::ImageKind::tex2d: return "2d";
    case graph::ImageKind::tex2d_array: return "2d-array";
    case graph::ImageKind::tex3d: return "3d";
    case graph::ImageKind::cube: return "cube";
    }
    return "?";
}

json loc(const SourceLoc& l) { return {{"file", l.file}, {"line", l.line}, {"col", l.col}}; }

json param_json(const graph::ParamDesc& p) {
    json j = {{"name", p.name}, {"type", param_type(p.type)}, {"widget", widget_kind(p)}, {"loc", loc(p.loc)}};
    if (p.type == ParamType::enumeration) {
        size_t i = static_cast<size_t>(p.value[0]);
        j["value"] = i < p.options.size() ? p.options[i] : "";
        j["options"] = p.options;
    } else if (p.type == ParamType::boolean) {
        j["value"] = p.value[0] != 0.0;
    } else if (p.type == ParamType::i32) {
        j["value"] = static_cast<int64_t>(p.value[0]);
    } else if (p.components() == 1) {
        j["value"] = p.value[0];
    } else {
        j["value"] = std::vector<double>(p.value.begin(), p.value.begin() + p.components());
    }
    if (p.min) j["min"] = *p.min;
    if (p.max) j["max"] = *p.max;
    if (p.log) j["log"] = true;
    if (!p.doc.empty()) j["doc"] = p.doc;
    return j;
}

} // namespace

json describe_graph(const exec::CompiledGraph& g) {
    const auto env = exec::size_env(g.desc, g.view);
    json passes = json::array();
    for (const auto& p : g.passes) {
        json shaders = json::array();
        for (const auto& f : p.program.dependencies) shaders.push_back(f.string());
        passes.push_back({{"name", p.desc->name},
                          {"kind", graph::kind_name(p.desc->kind)},
                          {"reads", p.io.reads},
                          {"writes", p.io.writes},
                          {"repeat", p.repeat},
                          {"files", shaders},
                          {"loc", loc(p.desc->loc)}});
    }
    json images = json::array();
    for (const auto& i : g.desc.images) {
        json j = {{"name", i.name}, {"kind", image_kind(i.kind)}, {"format", i.format}, {"mips", i.mips}, {"loc", loc(i.loc)}};
        if (auto e = graph::eval_extent(i.size, env, i.kind == graph::ImageKind::tex3d ? 3 : 2)) {
            j["size"] = json::array({e->w, e->h});
            if (i.kind == graph::ImageKind::tex3d) j["size"].push_back(e->d);
        }
        if (!i.size.text.empty()) j["size_expr"] = i.size.text;
        if (i.kind == graph::ImageKind::tex2d_array) j["layers"] = i.layers;
        if (i.samples > 1) j["samples"] = i.samples;
        if (i.history) j["history"] = true;
        if (!i.file.empty()) j["file"] = i.file;
        if (!i.generator.empty()) j["generator"] = i.generator;
        images.push_back(j);
    }
    json buffers = json::array();
    for (const auto& b : g.desc.buffers) {
        json j = {{"name", b.name}, {"loc", loc(b.loc)}};
        if (auto n = graph::eval_scalar(b.size, env)) j["bytes"] = *n;
        buffers.push_back(j);
    }
    json params = json::array();
    for (const auto& p : g.desc.params) params.push_back(param_json(p));
    json tests = json::array();
    for (const auto& t : g.desc.tests) tests.push_back(t.name);
    return {{"preset", g.desc.file.string()},
            {"title", g.desc.meta.title},
            {"view", {g.view[0], g.view[1]}},
            {"output", g.desc.output},
            {"passes", passes},
            {"images", images},
            {"buffers", buffers},
            {"params", params},
            {"tests", tests},
            {"files", [&] {
                 json f = json::array();
                 for (const auto& d : g.dependencies) f.push_back(d.string());
                 return f;
             }()}};
}

} // namespace pl::lab
