#include "import/media.hpp"

#include "import/source_text.hpp"

#include <filesystem>

namespace pl::import {

std::string sampler_toml(const ChannelSampler& s) {
    std::string f = s.filter == "nearest" ? "filter = \"nearest\", mip_filter = \"nearest\""
                    : s.filter == "mipmap" ? "filter = \"linear\", mip_filter = \"linear\""
                                           : "filter = \"linear\", mip_filter = \"nearest\"";
    return "{ " + f + ", address = \"" + (s.wrap == "repeat" ? "repeat" : "clamp") + "\" }";
}

MediaImage media_image(const Channel& c, const std::string& name, const std::string& where) {
    MediaImage m;
    const std::string mips = c.sampler.filter == "mipmap" ? ", mips = \"full\"" : "";
    const std::string sampler = ", sampler = " + sampler_toml(c.sampler);
    const std::string upload = std::string(c.sampler.vflip ? ", flip_y = true" : "") + (c.sampler.srgb ? ", srgb = true" : "");
    if (!c.file.empty() && c.kind == ChannelKind::texture) {
        m.copy = "media/" + name + std::filesystem::path(c.file).extension().string();
        m.image = "{ file = " + toml_quote(m.copy) + upload + mips + sampler + " }";
        return m;
    }
    auto warn = [&](const std::string& what, const std::string& stand_in) {
        m.warning = where + ": " + what + " '" + c.media + "' is replaced by " + stand_in;
    };
    switch (c.kind) {
    case ChannelKind::texture:
        // Noise textures are what most shaders sample: one random value per texel (a value
        // noise whose lattice is the texel grid), 256x256 like Shadertoy's "Gray Noise Medium".
        m.image = "{ generator = \"value-noise\", size = [256, 256], args = { frequency = 256 }" + upload + mips + sampler + " }";
        warn("the texture", "a procedural stand-in (256x256 per-texel noise); give the real one with --set " + name + "=FILE");
        break;
    case ChannelKind::volume:
        m.image = "{ kind = \"3d\", generator = \"value-noise\", size = [32, 32, 32], args = { frequency = 32 }" + mips + sampler + " }";
        warn("the volume", "a procedural stand-in (32x32x32 per-texel noise)");
        break;
    case ChannelKind::cubemap:
        m.image = "{ kind = \"cube\", format = \"rgba16f\", size = 256" + sampler + " }";
        m.sky_pass = true;
        warn("the cube map", "a procedural sky (256x256 per face)");
        break;
    case ChannelKind::video:
    case ChannelKind::webcam:
        m.image = "{ generator = \"uv-grid\", size = [512, 512]" + upload + mips + sampler + " }";
        warn(c.kind == ChannelKind::video ? "the video" : "the webcam", "a still uv grid (video input is not supported)");
        break;
    case ChannelKind::audio:
        // Shadertoy's audio texture: 512x2, FFT row and waveform row; silence here.
        m.image = "{ generator = \"constant\", size = [512, 2], args = { value = [0, 0, 0, 0] }" + sampler + " }";
        warn("the audio input", "silence (audio input is not supported)");
        break;
    default: break;
    }
    return m;
}

} // namespace pl::import
