// A Shadertoy shader as read from any of its source forms (API JSON, a mainImage file, a folder):
// tabs with their code and channels. shadertoy_preset.cpp turns it into a preset.
#pragma once

#include "util/error.hpp"

#include <array>
#include <string>
#include <vector>

namespace pl::import {

// The per-channel sampler of Shadertoy's JSON ("sampler": {filter, wrap, vflip, srgb}).
struct ChannelSampler {
    std::string filter = "linear";  // nearest | linear | mipmap
    std::string wrap = "clamp";     // clamp | repeat
    bool vflip = true;              // media only: the picture's bottom row at v = 0
    bool srgb = false;              // media only: values decoded from sRGB
    bool operator==(const ChannelSampler&) const = default;
};

enum class ChannelKind { none, buffer, cube_buffer, texture, cubemap, volume, keyboard, video, webcam, audio };

struct Channel {
    ChannelKind kind = ChannelKind::none;
    int buffer = -1;     // buffer: 0..3 = Buffer A..D
    std::string media;   // media: the Shadertoy source path or name (for the stand-in and warning)
    std::string file;    // media: a user image file (absolute), instead of the stand-in
    ChannelSampler sampler;
    SourceLoc loc;       // where the source declares it (errors: a buffer with no tab ...)
};

enum class TabKind { common, buffer, cube, image, sound };

struct Tab {
    TabKind kind = TabKind::image;
    int index = 0;          // buffer: 0..3
    std::string label;      // "Buffer B": the name Shadertoy shows
    std::string file;       // "buffer_b.glsl": the file written into the preset
    std::string code;       // cleaned source (BOM/CRLF removed; line count kept)
    std::string origin;     // where errors in it are reported from: "Buffer B" or the user's file
    std::array<Channel, 4> channels;
};

struct Toy {
    std::string title, author, description, license, source;  // source: "shadertoy:ID" or the path
    std::vector<std::string> tags;
    std::vector<Tab> tabs;
    std::vector<std::string> warnings;  // one line each (unsupported features, stand-ins)
};

// Every buffer a channel reads has its tab, there is one Image tab, no tab twice.
Status check_toy(const Toy& toy, const SourceLoc& whole);

// Tab labels and files by buffer index: "Buffer A".."Buffer D", buffer_a.glsl.. buffer_d.glsl.
std::string buffer_label(int index);
std::string buffer_name(int index);  // buffer_a .. buffer_d: image, pass and file stem

} // namespace pl::import
