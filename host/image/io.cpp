// Image files through OpenImageIO. Writes go to a temporary file that is renamed into place, so
// an interrupted run never leaves a truncated PNG behind.
#include "image/image.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>

namespace fs = std::filesystem;

namespace pl::image {

Result<Image> load_image(const fs::path& file) {
    auto in = OIIO::ImageInput::open(file.string());
    if (!in) return make_error("cannot read image '" + file.string() + "': " + OIIO::geterror());
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.width > 16384 || spec.height > 16384)
        return make_error("image '" + file.string() + "' has an unsupported size");
    int nc = spec.nchannels;
    std::vector<float> raw(static_cast<size_t>(spec.width) * spec.height * nc);
    if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, raw.data()))
        return make_error("cannot decode image '" + file.string() + "': " + in->geterror());
    Image img;
    img.width = spec.width;
    img.height = spec.height;
    img.pixels.resize(static_cast<size_t>(img.width) * img.height * 4);
    for (size_t i = 0; i < static_cast<size_t>(img.width) * img.height; ++i) {
        const float* s = &raw[i * nc];
        float* d = &img.pixels[i * 4];
        if (nc >= 3) d[0] = s[0], d[1] = s[1], d[2] = s[2];
        else d[0] = d[1] = d[2] = s[0];  // gray (+ alpha)
        d[3] = nc == 4 ? s[3] : nc == 2 ? s[1] : 1.0f;
    }
    return img;
}

Status save_image(const Image& img, const fs::path& file, const SaveOptions& opt) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (ext != ".png" && ext != ".exr") return make_error("cannot write '" + file.string() + "': use .png or .exr");
    fs::path tmp = file;
    tmp += ".tmp" + ext;  // keep the extension: OIIO picks the format from it
    auto out = OIIO::ImageOutput::create(tmp.string());
    if (!out) return make_error("cannot write '" + file.string() + "': " + OIIO::geterror());
    bool png = ext == ".png";
    OIIO::ImageSpec spec(img.width, img.height, 4,
                         png ? OIIO::TypeDesc::UINT8 : (opt.exr_half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT));
    if (png) spec.attribute("png:compressionLevel", opt.png_compression);
    else spec.attribute("compression", "zip");
    if (!out->open(tmp.string(), spec)) return make_error("cannot write '" + file.string() + "': " + out->geterror());
    bool ok;
    if (png) {
        // Round to nearest after clamping: OIIO's own conversion would do the same, explicitly here.
        std::vector<uint8_t> bytes(img.pixels.size());
        for (size_t i = 0; i < bytes.size(); ++i) {
            float v = img.pixels[i];
            bytes[i] = static_cast<uint8_t>(std::lround(std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f) * 255.0f));
        }
        ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
    } else {
        ok = out->write_image(OIIO::TypeDesc::FLOAT, img.pixels.data());
    }
    ok = out->close() && ok;
    std::error_code ec;
    if (!ok) {
        fs::remove(tmp, ec);
        return make_error("cannot write '" + file.string() + "': " + out->geterror());
    }
    fs::rename(tmp, file, ec);
    if (ec) return make_error("cannot write '" + file.string() + "': " + ec.message());
    return ok_status();
}

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }
float linear_to_srgb(float c) { return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

} // namespace pl::image
