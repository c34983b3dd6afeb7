// Image files. Reading (any format) and EXR writing use OpenImageIO, loaded as a plugin on
// first use (see oiio_plugin/plugin.cpp for why). 8-bit PNG writing — every `render` and every
// golden — uses stb_image_write, linked directly, so the common path never loads OpenImageIO's
// ~260 libraries. Writes go to a temporary file that is renamed into place, so an interrupted
// run never leaves a truncated image behind.
#include "image/exr_header.hpp"
#include "image/image.hpp"
#include "util/files.hpp"

#include <dlfcn.h>
#include <stb/stb_image_write.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <mutex>
#include <vector>

namespace fs = std::filesystem;

namespace pl::image {

namespace {

struct Plugin {
    int (*load)(const char*, unsigned long long, int*, int*, float**, char*, size_t) = nullptr;
    void (*free_pixels)(float*) = nullptr;
    int (*save)(const char*, int, int, const float*, int, int, char*, size_t) = nullptr;
    std::string error;
};

const Plugin& plugin() {
    static Plugin p;
    static std::once_flag once;
    std::call_once(once, [] {
        const char* env = std::getenv("PASSLAB_OIIO_PLUGIN");
        std::string path = env ? env : PASSLAB_OIIO_PLUGIN;
        void* h = dlopen(path.c_str(), RTLD_NOW | RTLD_LOCAL);
        if (!h) {
            p.error = std::string("cannot load the image I/O plugin '") + path + "': " + dlerror();
            return;
        }
        p.load = reinterpret_cast<decltype(p.load)>(dlsym(h, "pl_oiio_load"));
        p.free_pixels = reinterpret_cast<decltype(p.free_pixels)>(dlsym(h, "pl_oiio_free"));
        p.save = reinterpret_cast<decltype(p.save)>(dlsym(h, "pl_oiio_save"));
        if (!p.load || !p.free_pixels || !p.save) p.error = "the image I/O plugin '" + path + "' lacks its functions";
    });
    return p;
}

// Bytes an image may take to decode: what the system has available now (MemAvailable), so an
// image too large for this machine is an error before anything is allocated rather than an
// out-of-memory abort; set_decode_limit() lowers it (the fuzz target's 2 GB budget).
unsigned long long decode_limit_override = 0;

unsigned long long decode_limit() {
    if (decode_limit_override) return decode_limit_override;
    std::ifstream meminfo("/proc/meminfo");
    for (std::string key; meminfo >> key;) {
        unsigned long long kib = 0;
        if (key == "MemAvailable:" && meminfo >> kib) return kib * 1024;
        meminfo.ignore(256, '\n');
    }
    return ~0ull;  // unknown: OpenImageIO's own failure is the error
}

Error environment_error(std::string msg) {
    Error e = make_error(std::move(msg));
    e.code = ExitCode::environment;
    return e;
}

} // namespace

void set_decode_limit(unsigned long long bytes) { decode_limit_override = bytes; }

Result<Image> load_image(const fs::path& file) {
    // A FIFO or /dev/zero would block the reader or make it seek forever.
    if (auto ok = check_regular_file(file, max_asset_bytes, "image"); !ok) return ok.error();
    const Plugin& p = plugin();
    if (!p.error.empty()) return environment_error(p.error);
    if (auto ok = check_exr_header(file); !ok) return ok.error();
    char err[512] = {0};
    Image img;
    float* pixels = nullptr;
    if (p.load(file.c_str(), decode_limit(), &img.width, &img.height, &pixels, err, sizeof err) != 0)
        return make_error("cannot read image '" + file.string() + "': " + err);
    img.pixels.assign(pixels, pixels + static_cast<size_t>(img.width) * img.height * 4);
    p.free_pixels(pixels);
    return img;
}

Status save_image(const Image& img, const fs::path& file, const SaveOptions& opt) {
    std::string ext = file.extension().string();
    std::transform(ext.begin(), ext.end(), ext.begin(), ::tolower);
    if (ext != ".png" && ext != ".exr") return make_error("cannot write '" + file.string() + "': use .png or .exr");
    fs::path tmp = file;
    tmp += ".tmp" + ext;  // keep the extension: the codec is chosen from it
    std::error_code ec;
    if (ext == ".png") {
        size_t n = img.pixels.size();
        std::vector<unsigned char> bytes(n);
        for (size_t i = 0; i < n; ++i) {
            float v = img.pixels[i];
            bytes[i] = static_cast<unsigned char>(std::lround(std::clamp(std::isfinite(v) ? v : 0.0f, 0.0f, 1.0f) * 255.0f));
        }
        // stb's level is zlib-like (higher = smaller); its default is 8.
        stbi_write_png_compression_level = std::clamp(opt.png_compression, 1, 9);
        if (!stbi_write_png(tmp.c_str(), img.width, img.height, 4, bytes.data(), img.width * 4)) {
            fs::remove(tmp, ec);
            return make_error("cannot write '" + file.string() + "'");
        }
        fs::rename(tmp, file, ec);
        if (ec) return make_error("cannot write '" + file.string() + "': " + ec.message());
        return ok_status();
    }
    const Plugin& p = plugin();
    if (!p.error.empty()) return environment_error(p.error);
    char err[512] = {0};
    if (p.save(tmp.c_str(), img.width, img.height, img.pixels.data(), opt.png_compression, opt.exr_half ? 1 : 0, err,
               sizeof err) != 0) {
        std::error_code ec;
        fs::remove(tmp, ec);
        return make_error("cannot write '" + file.string() + "': " + err);
    }
    fs::rename(tmp, file, ec);
    if (ec) return make_error("cannot write '" + file.string() + "': " + ec.message());
    return ok_status();
}

float srgb_to_linear(float c) { return c <= 0.04045f ? c / 12.92f : std::pow((c + 0.055f) / 1.055f, 2.4f); }
Image display_copy(const Image& img, bool* tone_mapped) {
    bool out_of_range = false, negative = false;
    for (size_t i = 0; i < img.pixels.size(); ++i) {
        if (i % 4 == 3) continue;
        const float v = img.pixels[i];
        if (!(v >= 0.0f && v <= 1.0f)) out_of_range = true;
        if (v < 0.0f) negative = true;
    }
    if (tone_mapped) *tone_mapped = out_of_range;
    if (!out_of_range) return img;
    Image out = img;
    for (size_t i = 0; i < out.pixels.size(); ++i) {
        if (i % 4 == 3) { out.pixels[i] = 1.0f; continue; }  // the alpha of HDR data is rarely coverage
        const float v = std::isfinite(out.pixels[i]) ? out.pixels[i] : 0.0f;
        const float m = linear_to_srgb(std::fabs(v) / (1.0f + std::fabs(v)));
        // Signed data (normals, velocities): 0 is mid grey, negatives the lower half.
        out.pixels[i] = negative ? 0.5f + (v < 0.0f ? -0.5f : 0.5f) * m : m;
    }
    return out;
}

float linear_to_srgb(float c) { return c <= 0.0031308f ? c * 12.92f : 1.055f * std::pow(c, 1.0f / 2.4f) - 0.055f; }

} // namespace pl::image
