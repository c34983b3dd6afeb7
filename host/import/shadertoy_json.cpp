// Shadertoy's API JSON (what shadertoy.com/api/v1/shaders/ID serves and export tools write):
// {"Shader": {"info": {...}, "renderpass": [...]}}, the bare inner object, or an array of them.
#include "import/shadertoy_read.hpp"

#include "import/source_text.hpp"

#include <nlohmann/json.hpp>

#include <fstream>
#include <regex>
#include <sstream>

namespace pl::import {

namespace {

using json = nlohmann::json;

struct JsonSource {
    std::string file, text;
    // Where `"key": "value"` (or `"key": value`) first occurs, for errors: JSON values carry no
    // location in nlohmann::json, and a search finds the one the user has to look at.
    SourceLoc locate(const std::string& key, const std::string& value = {}) const {
        std::string pat = "\"" + key + "\"\\s*:";
        if (!value.empty()) pat += "\\s*\"?" + std::regex_replace(value, std::regex(R"([.^$|()\[\]{}*+?\\])"), R"(\$&)");
        std::smatch m;
        if (std::regex_search(text, m, std::regex(pat))) {
            auto [l, c] = line_col(text, static_cast<size_t>(m.position(0)));
            return {file, l, c};
        }
        return {file, 1, 1};
    }
    Error error(const std::string& msg, SourceLoc loc) const {
        Error e = make_error(msg, loc);
        e.source_line = read_source_line(loc.file, loc.line);
        return e;
    }
};

std::string str(const json& j, const char* key) {
    if (!j.is_object() || !j.contains(key)) return {};
    const json& v = j[key];
    if (v.is_string()) return v.get<std::string>();
    if (v.is_number_integer()) return std::to_string(v.get<long long>());
    if (v.is_boolean()) return v.get<bool>() ? "true" : "false";
    return {};
}

// Buffer A..D and Cube A by the ids and preview paths Shadertoy uses for them (older exports:
// numbers 257..260 and 41; newer: the strings below).
int buffer_of(const std::string& id, const std::string& src) {
    static const char* ids[4][3] = {{"257", "4dXGR8", "buffer00"}, {"258", "XsXGR8", "buffer01"},
                                    {"259", "4sXGR8", "buffer02"}, {"260", "XdfGR8", "buffer03"}};
    for (int i = 0; i < 4; ++i)
        if (id == ids[i][0] || id == ids[i][1] || src.find(ids[i][2]) != std::string::npos) return i;
    return -1;
}
bool is_cube_a(const std::string& id, const std::string& src) {
    return id == "41" || id == "4dX3Rr" || src.find("cubemap00") != std::string::npos;
}

Result<Channel> read_input(const JsonSource& js, const json& in, const std::string& tab) {
    Channel c;
    const std::string ctype = str(in, "ctype"), id = str(in, "id"), src = str(in, "src");
    const std::string where = tab + ": input " + (id.empty() ? src : id);
    if (in.contains("sampler") && in["sampler"].is_object()) {
        const json& s = in["sampler"];
        if (auto f = str(s, "filter"); !f.empty()) {
            if (f != "nearest" && f != "linear" && f != "mipmap")
                return js.error(where + ": sampler filter '" + f + "' is not nearest, linear or mipmap", js.locate("filter", f));
            c.sampler.filter = f;
        }
        if (auto w = str(s, "wrap"); !w.empty()) {
            if (w != "clamp" && w != "repeat")
                return js.error(where + ": sampler wrap '" + w + "' is not clamp or repeat", js.locate("wrap", w));
            c.sampler.wrap = w;
        }
        c.sampler.vflip = str(s, "vflip") != "false";
        c.sampler.srgb = str(s, "srgb") == "true";
    }
    if (ctype == "buffer") {
        c.kind = ChannelKind::buffer;
        c.buffer = buffer_of(id, src);
        if (c.buffer < 0) return js.error(where + ": a buffer input that names no Buffer A..D", js.locate("src", src));
    } else if (ctype == "cubemap" && is_cube_a(id, src)) {
        c.kind = ChannelKind::cube_buffer;
    } else if (ctype == "texture") c.kind = ChannelKind::texture;
    else if (ctype == "cubemap") c.kind = ChannelKind::cubemap;
    else if (ctype == "volume") c.kind = ChannelKind::volume;
    else if (ctype == "keyboard") c.kind = ChannelKind::keyboard;
    else if (ctype == "video") c.kind = ChannelKind::video;
    else if (ctype == "webcam") c.kind = ChannelKind::webcam;
    else if (ctype == "music" || ctype == "musicstream" || ctype == "mic") c.kind = ChannelKind::audio;
    else {
        Error e = js.error(where + ": unknown channel type '" + ctype + "'", js.locate("ctype", ctype));
        e.hint = "Shadertoy channel types: buffer, texture, cubemap, volume, keyboard, video, webcam, music, musicstream, mic";
        return e;
    }
    c.media = src.empty() ? ctype : src;
    c.loc = js.locate(id.empty() ? "src" : "id", id.empty() ? src : id);
    return c;
}

Result<Tab> read_pass(const JsonSource& js, const json& rp, size_t k) {
    Tab t;
    const std::string type = str(rp, "type"), name = str(rp, "name");
    t.label = name.empty() ? type : name;
    if (type == "image") t.kind = TabKind::image, t.file = "image.glsl", t.label = "Image";
    else if (type == "common") t.kind = TabKind::common, t.file = "common.glsl", t.label = "Common";
    else if (type == "sound") t.kind = TabKind::sound, t.file = "sound.glsl", t.label = "Sound";
    else if (type == "cubemap") t.kind = TabKind::cube, t.file = "cube_a.glsl", t.label = "Cube A";
    else if (type == "buffer") {
        t.kind = TabKind::buffer;
        int b = -1;
        if (rp.contains("outputs") && rp["outputs"].is_array() && !rp["outputs"].empty())
            b = buffer_of(str(rp["outputs"][0], "id"), "");
        if (b < 0 && name.size() == 8 && name.rfind("Buffer ", 0) == 0 && name[7] >= 'A' && name[7] <= 'D') b = name[7] - 'A';
        if (b < 0) return js.error("renderpass " + std::to_string(k) + " ('" + name + "') is a buffer but neither its output id nor its name says which of Buffer A..D",
                                   js.locate("name", name));
        t.index = b;
        t.label = buffer_label(b);
        t.file = buffer_name(b) + ".glsl";
    } else {
        Error e = js.error("renderpass " + std::to_string(k) + " has type '" + type + "'", js.locate("type", type));
        e.hint = "Shadertoy pass types: image, buffer, common, cubemap, sound";
        return e;
    }
    if (!rp.contains("code") || !rp["code"].is_string())
        return js.error("renderpass '" + t.label + "' has no \"code\" string", js.locate("name", name));
    t.code = glsl_es_to_450(rp["code"].get<std::string>());
    t.origin = t.label;
    if (rp.contains("inputs") && rp["inputs"].is_array()) {
        for (const json& in : rp["inputs"]) {
            auto c = read_input(js, in, t.label);
            if (!c) return c.error();
            int ch = in.contains("channel") && in["channel"].is_number_integer() ? in["channel"].get<int>() : -1;
            if (ch < 0 || ch > 3) return js.error(t.label + ": input without a channel 0..3", js.locate("channel"));
            t.channels[static_cast<size_t>(ch)] = *c;
        }
    }
    return t;
}

} // namespace

Result<Toy> read_shadertoy_json(const std::filesystem::path& file) {
    auto text = read_text_file(file);
    if (!text) return text.error();
    JsonSource js{file.string(), clean_text(*text)};
    json root;
    try {
        root = json::parse(js.text);
    } catch (const json::parse_error& e) {
        auto [l, c] = line_col(js.text, e.byte > 0 ? e.byte - 1 : 0);
        return js.error(std::string("invalid JSON: ") + e.what(), {js.file, l, c});
    }
    Toy toy;
    if (root.is_array()) {
        if (root.empty()) return js.error("an empty array: no Shadertoy shader in it", {js.file, 1, 1});
        if (root.size() > 1)
            toy.warnings.push_back(js.file + ": holds " + std::to_string(root.size()) + " shaders; importing the first");
        root = root[0];
    }
    if (root.is_object() && root.contains("Shader")) root = root["Shader"];
    if (!root.is_object() || !root.contains("renderpass") || !root["renderpass"].is_array()) {
        Error e = js.error("not a Shadertoy shader: expected {\"Shader\": {\"info\": ..., \"renderpass\": [...]}}", {js.file, 1, 1});
        e.hint = "export from shadertoy.com (or its API, /api/v1/shaders/ID) writes that shape";
        return e;
    }
    const json info = root.contains("info") ? root["info"] : json::object();
    toy.title = str(info, "name");
    toy.author = str(info, "username");
    toy.description = str(info, "description");
    toy.source = str(info, "id").empty() ? file.filename().string() : "shadertoy:" + str(info, "id");
    toy.license = "see the author's page (Shadertoy's default: CC BY-NC-SA 3.0)";
    if (info.contains("tags") && info["tags"].is_array())
        for (const json& t : info["tags"])
            if (t.is_string()) toy.tags.push_back(t.get<std::string>());
    size_t k = 0;
    for (const json& rp : root["renderpass"]) {
        auto t = read_pass(js, rp, k++);
        if (!t) return t.error();
        toy.tabs.push_back(std::move(*t));
    }
    if (auto s = check_toy(toy, {js.file, 1, 1}); !s) return s.error();
    return toy;
}

} // namespace pl::import
