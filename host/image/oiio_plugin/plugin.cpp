// The OpenImageIO side of image file I/O, built as a plugin that passlab loads (dlopen) only
// when it reads or writes an image file. OpenImageIO pulls in ~260 shared libraries; linked
// into the executable they cost every run ~0.2 s of start-up and ~130 MB of resident memory,
// even `passlab check`, which never touches an image file.
#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <exception>
#include <string>
#include <vector>

namespace {
void set_error(char* err, size_t n, const std::string& msg) {
    if (n == 0) return;
    std::strncpy(err, msg.c_str(), n - 1);
    err[n - 1] = '\0';
}
} // namespace

extern "C" {

// Loads any format OpenImageIO reads as RGBA float (gray -> rgb, missing alpha = 1).
// *pixels is malloc'ed; free it with pl_oiio_free. Returns 0 on success.
// `max_bytes` bounds what decoding may allocate here and in the caller's copy of the pixels.
int pl_oiio_load(const char* path, unsigned long long max_bytes, int* width, int* height, float** pixels, char* err,
                 size_t errlen) {
    auto in = OIIO::ImageInput::open(path);
    if (!in) {
        set_error(err, errlen, OIIO::geterror());
        return 1;
    }
    const OIIO::ImageSpec& spec = in->spec();
    if (spec.width <= 0 || spec.height <= 0 || spec.width > 16384 || spec.height > 16384) {
        set_error(err, errlen, "unsupported size " + std::to_string(spec.width) + "x" + std::to_string(spec.height));
        return 1;
    }
    // read_image fills width x height x depth x nchannels floats: a volume file (DDS, OpenVDB)
    // or a header claiming thousands of channels would overrun a buffer sized for one 2D
    // RGBA-ish slice, so both are refused here (3D textures come from generators).
    if (spec.depth != 1) {
        set_error(err, errlen, "3D image files (depth " + std::to_string(spec.depth) + ") are not supported");
        return 1;
    }
    const int nc = spec.nchannels;
    if (nc < 1 || nc > 64) {
        set_error(err, errlen, "unsupported channel count " + std::to_string(nc));
        return 1;
    }
    const size_t n = static_cast<size_t>(spec.width) * spec.height;
    // The decoded channels, the RGBA float result, and load_image's copy of it.
    const unsigned long long need = n * static_cast<unsigned long long>(nc) * 4 + 2ull * n * 16;
    if (need > max_bytes) {
        set_error(err, errlen, "a " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " image of " +
                                   std::to_string(nc) + " channels needs " + std::to_string(need >> 20) + " MiB to decode; " +
                                   std::to_string(max_bytes >> 20) + " MiB are available");
        return 1;
    }
    // No C++ exception may cross this extern "C" boundary: allocation failure is an error.
    std::vector<float> raw;
    try {
        raw.resize(n * static_cast<size_t>(nc));
    } catch (const std::exception&) {
        set_error(err, errlen, "out of memory for a " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " image");
        return 1;
    }
    if (!in->read_image(0, 0, 0, nc, OIIO::TypeDesc::FLOAT, raw.data())) {
        set_error(err, errlen, in->geterror());
        return 1;
    }
    float* out = static_cast<float*>(std::malloc(n * 4 * sizeof(float)));
    if (!out) {
        set_error(err, errlen, "out of memory for a " + std::to_string(spec.width) + "x" + std::to_string(spec.height) + " image");
        return 1;
    }
    for (size_t i = 0; i < n; ++i) {
        const float* s = &raw[i * nc];
        float* d = &out[i * 4];
        if (nc >= 3) d[0] = s[0], d[1] = s[1], d[2] = s[2];
        else d[0] = d[1] = d[2] = s[0];
        d[3] = nc == 4 ? s[3] : nc == 2 ? s[1] : 1.0f;
    }
    *width = spec.width;
    *height = spec.height;
    *pixels = out;
    return 0;
}

void pl_oiio_free(float* pixels) { std::free(pixels); }

// Writes RGBA float pixels: PNG as 8-bit (clamped, rounded) at zlib level `png_level`, EXR as
// half or float with zip compression. The format follows the file extension.
int pl_oiio_save(const char* path, int width, int height, const float* rgba, int png_level, int exr_half, char* err,
                 size_t errlen) {
    std::string p(path);
    bool png = p.size() > 4 && (p.substr(p.size() - 4) == ".png" || p.substr(p.size() - 4) == ".PNG");
    auto out = OIIO::ImageOutput::create(p);
    if (!out) {
        set_error(err, errlen, OIIO::geterror());
        return 1;
    }
    OIIO::ImageSpec spec(width, height, 4, png ? OIIO::TypeDesc::UINT8 : (exr_half ? OIIO::TypeDesc::HALF : OIIO::TypeDesc::FLOAT));
    if (png) spec.attribute("png:compressionLevel", png_level);
    else spec.attribute("compression", "zip");
    if (!out->open(p, spec)) {
        set_error(err, errlen, out->geterror());
        return 1;
    }
    bool ok;
    if (png) {
        size_t n = static_cast<size_t>(width) * height * 4;
        std::vector<uint8_t> bytes(n);
        for (size_t i = 0; i < n; ++i) {
            float v = rgba[i];
            bytes[i] = static_cast<uint8_t>(std::lround(std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f) * 255.0f));
        }
        ok = out->write_image(OIIO::TypeDesc::UINT8, bytes.data());
    } else {
        ok = out->write_image(OIIO::TypeDesc::FLOAT, rgba);
    }
    ok = out->close() && ok;
    if (!ok) {
        set_error(err, errlen, out->geterror());
        return 1;
    }
    return 0;
}

} // extern "C"
