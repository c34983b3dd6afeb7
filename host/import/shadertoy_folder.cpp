// The folder form of a Shadertoy shader (one file per tab) and the single mainImage file.
// channels.toml wires the iChannels, one table per tab:
//   [image]
//   iChannel0 = "buffer_a"                                   # buffer_a..buffer_d, cube_a, keyboard
//   iChannel1 = { buffer = "buffer_b", filter = "nearest", wrap = "repeat" }
//   iChannel2 = { texture = "RGBA Noise Medium" }            # a procedural stand-in
//   iChannel3 = { file = "photo.png", vflip = true, srgb = false, filter = "mipmap" }
#include "import/shadertoy_read.hpp"

#include "import/source_text.hpp"

#include <toml++/toml.h>

#include <fstream>
#include <sstream>

namespace pl::import {

namespace fs = std::filesystem;

namespace {

SourceLoc loc_of(const toml::node& n, const std::string& file) {
    return {file, static_cast<int>(n.source().begin.line), static_cast<int>(n.source().begin.column)};
}
Error at(const std::string& msg, const toml::node& n, const std::string& file) {
    Error e = make_error(msg, loc_of(n, file));
    e.source_line = read_source_line(file, e.loc.line);
    return e;
}

Result<Channel> buffer_ref(const std::string& name, const toml::node& n, const std::string& file) {
    Channel c;
    for (int b = 0; b < 4; ++b)
        if (name == buffer_name(b)) c.kind = ChannelKind::buffer, c.buffer = b;
    if (name == "cube_a") c.kind = ChannelKind::cube_buffer;
    if (name == "keyboard") c.kind = ChannelKind::keyboard, c.media = "keyboard";
    if (c.kind == ChannelKind::none) {
        Error e = at("'" + name + "' is not a channel source", n, file);
        e.hint = "buffer_a .. buffer_d, cube_a, keyboard, or a table { buffer | texture | cubemap | volume | video | webcam | audio | file = ... }";
        return e;
    }
    c.loc = loc_of(n, file);
    return c;
}

Result<Channel> read_channel(const toml::node& n, const std::string& file, const fs::path& dir) {
    if (auto s = n.as_string()) return buffer_ref(s->get(), n, file);
    const toml::table* t = n.as_table();
    if (!t) return at("a channel is a source name (\"buffer_a\") or a table", n, file);
    Channel c;
    c.loc = loc_of(n, file);
    int sources = 0;
    static const std::pair<const char*, ChannelKind> media[] = {
        {"texture", ChannelKind::texture}, {"cubemap", ChannelKind::cubemap}, {"volume", ChannelKind::volume},
        {"video", ChannelKind::video},     {"webcam", ChannelKind::webcam},   {"audio", ChannelKind::audio}};
    for (const auto& entry : *t) {
        // Not a structured binding: clang 14 (the fuzz build) cannot capture one in a lambda.
        const std::string k(entry.first.str());
        const toml::node& val = entry.second;
        auto text = [&]() -> Result<std::string> {
            if (auto s = val.as_string()) return s->get();
            return at("'" + k + "' must be a string", val, file);
        };
        auto flag = [&]() -> Result<bool> {
            if (auto b = val.as_boolean()) return b->get();
            return at("'" + k + "' must be true or false", val, file);
        };
        if (k == "buffer") {
            auto s = text();
            if (!s) return s.error();
            auto b = buffer_ref(*s, val, file);
            if (!b) return b.error();
            c.kind = b->kind, c.buffer = b->buffer, c.media = b->media;
            ++sources;
        } else if (k == "file") {
            auto s = text();
            if (!s) return s.error();
            c.file = (dir / *s).lexically_normal().string();
            std::error_code ec;
            if (!fs::is_regular_file(c.file, ec)) return at("channel file '" + *s + "' does not exist in " + dir.string(), val, file);
            c.kind = c.kind == ChannelKind::none ? ChannelKind::texture : c.kind;
            c.media = *s;
            ++sources;
        } else if (k == "filter" || k == "wrap") {
            auto s = text();
            if (!s) return s.error();
            bool ok = k == "filter" ? (*s == "nearest" || *s == "linear" || *s == "mipmap") : (*s == "clamp" || *s == "repeat");
            if (!ok) return at(k + " '" + *s + "' is not " + (k == "filter" ? "nearest, linear or mipmap" : "clamp or repeat"), val, file);
            (k == "filter" ? c.sampler.filter : c.sampler.wrap) = *s;
        } else if (k == "vflip" || k == "srgb") {
            auto b = flag();
            if (!b) return b.error();
            (k == "vflip" ? c.sampler.vflip : c.sampler.srgb) = *b;
        } else {
            bool found = false;
            for (const auto& [mk, kind] : media)
                if (k == mk) {
                    auto s = text();
                    if (!s) return s.error();
                    if (c.file.empty() || c.kind == ChannelKind::texture) c.kind = kind;
                    if (c.media.empty()) c.media = *s;
                    found = true;
                    ++sources;
                }
            if (!found) {
                Error e = at("unknown channel key '" + k + "'", val, file);
                e.hint = "keys: buffer, texture, cubemap, volume, video, webcam, audio, file, filter, wrap, vflip, srgb";
                return e;
            }
        }
    }
    // A file may come with the media kind it replaces (cubemap = "...", file = ...): two keys.
    if (sources == 0 || (sources > 1 && c.file.empty()))
        return at("a channel names exactly one source (buffer, texture, cubemap, volume, video, webcam, audio or file)", n, file);
    return c;
}

Status read_manifest(const fs::path& dir, Toy& toy) {
    const fs::path mf = dir / "channels.toml";
    std::error_code ec;
    if (!fs::exists(mf, ec)) return ok_status();
    const std::string file = mf.string();
    auto text = read_text_file(mf);
    if (!text) return text.error();
    toml::table root;
    try {
        root = toml::parse(clean_text(*text), file);
    } catch (const toml::parse_error& e) {
        Error err = make_error(std::string("invalid TOML: ") + std::string(e.description()),
                               {file, static_cast<int>(e.source().begin.line), static_cast<int>(e.source().begin.column)});
        err.source_line = read_source_line(file, err.loc.line);
        return err;
    }
    for (const auto& [key, val] : root) {
        const std::string k(key.str());
        if (k == "title" || k == "author" || k == "license" || k == "description") {
            auto s = val.as_string();
            if (!s) return at("'" + k + "' must be a string", val, file);
            (k == "title" ? toy.title : k == "author" ? toy.author : k == "license" ? toy.license : toy.description) = s->get();
            continue;
        }
        Tab* tab = nullptr;
        for (auto& t : toy.tabs)
            if (t.file == k + ".glsl") tab = &t;
        if (!tab) {
            Error e = at("[" + k + "]: no tab " + k + ".glsl in " + dir.string(), val, file);
            e.hint = "tables are named after the tab files: image, buffer_a .. buffer_d, cube_a; or the keys title, author, license, description";
            return e;
        }
        const toml::table* chans = val.as_table();
        if (!chans) return at("[" + k + "] must be a table of iChannel0..iChannel3", val, file);
        for (const auto& [ck, cv] : *chans) {
            const std::string name(ck.str());
            if (name.size() != 9 || name.rfind("iChannel", 0) != 0 || name[8] < '0' || name[8] > '3')
                return at("[" + k + "] '" + name + "': the keys are iChannel0 .. iChannel3", cv, file);
            auto c = read_channel(cv, file, dir);
            if (!c) return c.error();
            tab->channels[static_cast<size_t>(name[8] - '0')] = *c;
        }
    }
    return ok_status();
}

Result<Tab> read_tab(const fs::path& p, TabKind kind, int index, const std::string& label) {
    auto text = read_text_file(p);
    if (!text) return text.error();
    Tab t;
    t.kind = kind;
    t.index = index;
    t.label = label;
    t.file = p.filename().string();
    t.code = glsl_es_to_450(*text);
    t.origin = fs::absolute(p).lexically_normal().string();
    return t;
}

} // namespace

Result<Toy> read_shadertoy_file(const fs::path& file) {
    auto t = read_tab(file, TabKind::image, 0, "Image");
    if (!t) return t.error();
    t->file = "image.glsl";
    Toy toy;
    toy.title = file.stem().string();
    toy.source = file.filename().string();
    toy.tabs.push_back(std::move(*t));
    return toy;
}

Result<Toy> read_shadertoy_folder(const fs::path& dir) {
    Toy toy;
    toy.title = fs::absolute(dir).lexically_normal().filename().string();
    if (toy.title.empty()) toy.title = fs::absolute(dir).lexically_normal().parent_path().filename().string();
    toy.source = toy.title;
    std::error_code ec;
    struct Known { const char* file; TabKind kind; int index; const char* label; };
    static const Known known[] = {{"common.glsl", TabKind::common, 0, "Common"}, {"buffer_a.glsl", TabKind::buffer, 0, "Buffer A"},
                                  {"buffer_b.glsl", TabKind::buffer, 1, "Buffer B"}, {"buffer_c.glsl", TabKind::buffer, 2, "Buffer C"},
                                  {"buffer_d.glsl", TabKind::buffer, 3, "Buffer D"}, {"cube_a.glsl", TabKind::cube, 0, "Cube A"},
                                  {"image.glsl", TabKind::image, 0, "Image"},     {"sound.glsl", TabKind::sound, 0, "Sound"}};
    for (const auto& k : known) {
        if (!fs::is_regular_file(dir / k.file, ec)) continue;
        auto t = read_tab(dir / k.file, k.kind, k.index, k.label);
        if (!t) return t.error();
        toy.tabs.push_back(std::move(*t));
    }
    if (auto s = read_manifest(dir, toy); !s) return s.error();
    const fs::path mf = dir / "channels.toml";
    if (auto s = check_toy(toy, {fs::exists(mf, ec) ? mf.string() : (dir / "image.glsl").string(), 0, 0}); !s) return s.error();
    return toy;
}

} // namespace pl::import
