// A Shadertoy shader as an ordinary preset: Buffer A..D, Cube A and Image become passes in that
// order, buffers become view-sized rgba32f images (with history when a pass reads one that runs
// at or after it: Shadertoy shows it the previous frame), channels become bindings to the
// images or to aliases carrying that channel's sampler.
#include "import/import.hpp"

#include "import/media.hpp"
#include "import/shadertoy_glsl.hpp"
#include "import/source_text.hpp"
#include "import/toy.hpp"

#include <algorithm>
#include <map>
#include <set>

namespace pl::import {

namespace {

// Per-frame order: Buffer A..D (0..3), Cube A (4), Image (5).
int order_of(const Tab& t) { return t.kind == TabKind::buffer ? t.index : t.kind == TabKind::cube ? 4 : 5; }
std::string image_of(const Channel& c) { return c.kind == ChannelKind::buffer ? buffer_name(c.buffer) : "cube_a"; }
std::string pass_of(const Tab& t) { return t.kind == TabKind::buffer ? buffer_name(t.index) : t.kind == TabKind::cube ? "cube_a" : "image"; }

std::string sampler_suffix(const ChannelSampler& s) { return s.filter + "_" + s.wrap; }

struct Builder {
    const Toy& toy;
    const ImportOptions& opt;
    PresetFiles out;
    std::string images, passes, params;
    std::set<std::string> history, mipmapped;                 // rendered images
    std::map<std::string, ChannelSampler> base_sampler;         // image -> its own sampler
    std::set<std::string> aliases;
    std::vector<std::string> sky_passes;
    bool keyboard = false;  // some channel reads the keyboard: a pass draws it first each frame

    // The graph name a channel binds, creating the alias or media image it needs.
    std::string channel_resource(const Tab& t, size_t ch) {
        const Channel& c = t.channels[ch];
        const std::string where = t.label + " iChannel" + std::to_string(ch);
        if (c.kind == ChannelKind::none) return "pl_black";
        if (c.kind == ChannelKind::keyboard) {
            keyboard = true;  // one image for every channel that reads it
            return "pl_keyboard";
        }
        if (c.kind == ChannelKind::buffer || c.kind == ChannelKind::cube_buffer) {
            const std::string img = image_of(c);
            const int src_order = c.kind == ChannelKind::buffer ? c.buffer : 4;
            const bool prev = src_order >= order_of(t);  // itself or a later pass: last frame
            if (prev) history.insert(img);
            if (c.sampler.filter == "mipmap") mipmapped.insert(img);
            auto [it, fresh] = base_sampler.try_emplace(img, c.sampler);
            std::string name = img;
            if (!fresh && !(it->second == c.sampler)) {
                name = img + "_" + sampler_suffix(c.sampler);
                if (aliases.insert(name).second)
                    images += name + " = { alias = \"" + img + "\", sampler = " + sampler_toml(c.sampler) + " }\n";
            }
            return prev ? name + "_prev" : name;
        }
        const std::string name = pass_of(t) + "_ch" + std::to_string(ch);
        MediaImage m = media_image(c, name, where);
        images += name + " = " + m.image + "\n";
        if (!m.copy.empty()) out.copies[m.copy] = c.file, out.inputs.push_back(c.file);
        if (!m.warning.empty()) out.warnings.push_back(m.warning);
        if (m.sky_pass) sky_passes.push_back(name);
        return name;
    }

    ChannelDecl decl_of(const Channel& c) {
        ChannelDecl d;
        switch (c.kind) {
        case ChannelKind::none: d.comment = "not connected (black)"; break;
        case ChannelKind::buffer: d.comment = buffer_label(c.buffer); break;
        case ChannelKind::cube_buffer: d.type = "samplerCube", d.comment = "Cube A"; break;
        case ChannelKind::cubemap: d.type = "samplerCube", d.comment = "cube map " + c.media; break;
        case ChannelKind::volume: d.type = "sampler3D", d.comment = "volume " + c.media; break;
        default: d.comment = c.media; break;
        }
        return d;
    }

    Result<PresetFiles> build() {
        const Tab* common = nullptr;
        std::vector<const Tab*> runs;
        for (const auto& t : toy.tabs) {
            if (t.kind == TabKind::common) common = &t;
            else if (t.kind == TabKind::sound)
                out.warnings.push_back(t.label + ": mainSound is not supported (no audio output); the other tabs run");
            else runs.push_back(&t);
            if (t.kind != TabKind::sound) {
                out.files[t.file] = t.code;
                out.origins[t.file] = t.origin;
            }
        }
        std::stable_sort(runs.begin(), runs.end(), [](const Tab* a, const Tab* b) { return order_of(*a) < order_of(*b); });

        std::string pass_text;
        for (const Tab* t : runs) {
            std::array<ChannelDecl, 4> decls;
            std::string bind;
            for (size_t ch = 0; ch < 4; ++ch) {
                decls[ch] = decl_of(t->channels[ch]);
                bind += std::string(ch ? ", " : "") + "iChannel" + std::to_string(ch) + " = \"" + channel_resource(*t, ch) + "\"";
            }
            const std::string name = pass_of(*t);
            const std::string wrapper = name + ".frag";
            out.files[wrapper] = pass_wrapper(*t, decls, common != nullptr);
            out.origins[wrapper] = t->label + " (generated wrapper " + wrapper + ")";
            pass_text += "\n[[pass]]\nname     = \"" + name + "\"\nfragment = \"" + wrapper + "\"\n";
            if (t->kind == TabKind::cube) pass_text += "repeat   = 6\ntargets  = [{ image = \"cube_a\", layer = \"iteration\" }]\n";
            else pass_text += "targets  = [\"" + name + "\"]\n";
            pass_text += "bind     = { " + bind + " }\n";
            if (mipmapped.count(name) && t->kind == TabKind::buffer)
                pass_text += "\n[[pass]]\nname  = \"" + name + "_mips\"\nkind  = \"mips\"\nimage = \"" + name + "\"\n";
        }
        // Mip chains are known only once every channel is seen: a buffer sampled with "mipmap"
        // by a pass declared before its writer's mips pass would miss it; add the late ones.
        for (const Tab* t : runs) {
            const std::string name = pass_of(*t);
            if (t->kind == TabKind::buffer && mipmapped.count(name) && pass_text.find("\"" + name + "_mips\"") == std::string::npos) {
                const std::string head = "\n[[pass]]\nname     = \"" + name + "\"\n";
                size_t at = pass_text.find(head);
                size_t next = pass_text.find("\n[[pass]]", at + head.size());
                pass_text.insert(next == std::string::npos ? pass_text.size() : next,
                                 "\n[[pass]]\nname  = \"" + name + "_mips\"\nkind  = \"mips\"\nimage = \"" + name + "\"\n");
            }
        }

        std::string img_text;
        for (const Tab* t : runs) {
            const std::string name = pass_of(*t);
            ChannelSampler s = base_sampler.count(name) ? base_sampler[name] : ChannelSampler{};
            if (t->kind == TabKind::image) {
                img_text += "image = { format = \"rgba8\", size = \"view\" }\n";
                continue;
            }
            img_text += name + " = { " + (t->kind == TabKind::cube ? "kind = \"cube\", size = 1024, " : "size = \"view\", ") +
                        "format = \"rgba32f\"" + (history.count(name) ? ", history = true" : "") +
                        (mipmapped.count(name) ? ", mips = \"full\"" : "") + ", sampler = " + sampler_toml(s) + " }\n";
        }
        img_text += "pl_black = { generator = \"constant\", size = [1, 1], args = { value = [0, 0, 0, 0] } }\n";
        if (keyboard) {
            img_text += "pl_keyboard = { format = \"r8\", size = [256, 3], sampler = { filter = \"nearest\", address = \"clamp\" } }\n";
            out.files["pl_keyboard.frag"] = keyboard_shader();
        }
        // Passes that fill inputs before the tabs run: the cube faces of sky channels, the keyboard.
        std::string input_passes;
        if (!sky_passes.empty()) out.files["pl_sky_cube.frag"] = sky_cube_shader();
        for (const auto& s : sky_passes)
            input_passes += "\n[[pass]]\nname     = \"" + s + "_sky\"\nfragment = \"pl_sky_cube.frag\"\nbake     = true\nrepeat   = 6\n"
                        "targets  = [{ image = \"" + s + "\", layer = \"iteration\" }]\n";

        std::string t = "# Imported by `passlab import` from " + toy.source + " (docs/import.md).\n";
        t += "# Edit the tab files (image.glsl, buffer_a.glsl ...); the .frag files wrap them.\n";
        t += "[preset]\ntitle   = " + toml_quote(toy.title.empty() ? "Imported Shadertoy shader" : toy.title) + "\n";
        t += "family  = \"imported\"\n";
        std::string summary = toy.description.substr(0, toy.description.find('\n'));
        if (summary.size() > 160) summary = summary.substr(0, 157) + "...";
        t += "summary = " + toml_quote(summary.empty() ? "A Shadertoy shader." : summary) + "\n";
        std::string tags = "\"shadertoy\"";
        for (const auto& g : toy.tags) tags += ", " + toml_quote(g);
        t += "tags    = [" + tags + "]\n";
        if (!toy.author.empty()) t += "author  = " + toml_quote(toy.author) + "\n";
        if (!toy.license.empty()) t += "license = " + toml_quote(toy.license) + "\n";
        t += "source  = " + toml_quote(toy.source) + "\n";
        t += "\n[view]\nsize = [640, 360]\n";
        t += "\n[params]\ndate = { value = [2026.0, 0.0, 1.0, 43200.0], clock = \"date\", doc = \"iDate: year, month (0-11), day, seconds (iTime is added); run: the wall clock\" }\n";
        t += "\n[images]\n" + img_text + images;
        if (keyboard)
            input_passes += "\n[[pass]]\nname     = \"pl_keyboard\"\nfragment = \"pl_keyboard.frag\"\ntargets  = [\"pl_keyboard\"]\n";
        t += input_passes + pass_text;
        t += "\n[output]\nimage = \"image\"\n";
        if (opt.golden)
            t += "\n[[test]]\nname   = \"golden\"\nsize   = [320, 180]\ntime   = 1.0\nframes = 30\nstep   = 0.0333333\n"
                 "golden = \"golden.png\"\nhint   = \"the first `passlab test` records golden.png at t = 1 s and the pinned date\"\n";
        else
            t += "\n[[test]]\nname   = \"stable\"\nsize   = [320, 180]\ntime   = 1.0\nframes = 30\nstep   = 0.0333333\n"
                 "checks = [{ kind = \"stable\" }]\n";
        out.files["preset.toml"] = t;
        out.files["shadertoy.glsl"] = shadertoy_header();
        out.warnings.insert(out.warnings.begin(), toy.warnings.begin(), toy.warnings.end());
        return out;
    }
};

} // namespace

Result<PresetFiles> shadertoy_preset(const Toy& toy, const ImportOptions& o) {
    Builder b{toy, o, {}, {}, {}, {}, {}, {}, {}, {}, {}, false};
    return b.build();
}

} // namespace pl::import
