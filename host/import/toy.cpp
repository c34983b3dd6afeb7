#include "import/toy.hpp"

namespace pl::import {

std::string buffer_label(int index) { return std::string("Buffer ") + static_cast<char>('A' + index); }
std::string buffer_name(int index) { return std::string("buffer_") + static_cast<char>('a' + index); }

Status check_toy(const Toy& toy, const SourceLoc& whole) {
    bool buffers[4] = {}, image = false, cube = false;
    for (const auto& t : toy.tabs) {
        bool& seen = t.kind == TabKind::buffer ? buffers[t.index] : t.kind == TabKind::image ? image : cube;
        if (t.kind == TabKind::buffer || t.kind == TabKind::image || t.kind == TabKind::cube) {
            if (seen) return make_error("tab '" + t.label + "' appears twice", whole);
            seen = true;
        }
    }
    if (!image) {
        Error e = make_error("no Image tab: Shadertoy shows the Image pass, so every shader has one", whole);
        e.hint = "a folder needs image.glsl; a JSON renderpass with \"type\": \"image\"";
        return e;
    }
    for (const auto& t : toy.tabs)
        for (size_t ch = 0; ch < 4; ++ch) {
            const Channel& c = t.channels[ch];
            bool missing = (c.kind == ChannelKind::buffer && !buffers[c.buffer]) || (c.kind == ChannelKind::cube_buffer && !cube);
            if (!missing) continue;
            std::string what = c.kind == ChannelKind::buffer ? buffer_label(c.buffer) : "Cube A";
            Error e = make_error(t.label + ": iChannel" + std::to_string(ch) + " reads " + what + ", which has no tab",
                                 c.loc.known() ? c.loc : whole);
            e.source_line = read_source_line(e.loc.file, e.loc.line);
            e.hint = "add the " + what + " tab (" + (c.kind == ChannelKind::buffer ? buffer_name(c.buffer) : std::string("cube_a")) +
                     ".glsl in a folder) or point the channel elsewhere";
            return e;
        }
    return ok_status();
}

} // namespace pl::import
