// Shadertoy media channels (textures, cube maps, volumes, video, webcam, audio, keyboard) as
// preset images: the user's file when the channel names one, else a procedural stand-in the
// project generates (no downloads), with one warning naming it.
#pragma once

#include "import/toy.hpp"

#include <string>

namespace pl::import {

struct MediaImage {
    std::string image;       // the [images] inline table
    std::string copy;        // a file to copy into the preset ("media/x.png"), or empty
    bool sky_pass = false;   // a cube stand-in: rendered once by the generated sky pass
    std::string warning;     // empty when the real media is used
};

// `name` is the image's name; `where` ("Image iChannel2") names the channel in the warning.
MediaImage media_image(const Channel& c, const std::string& name, const std::string& where);
// Shadertoy's sampler as a [images] sampler table (filter, mip filter, address).
std::string sampler_toml(const ChannelSampler& s);

} // namespace pl::import
