// Fuzz target: an image file as a texture's `file = ...`, a golden or a `passlab compare` input
// reads it (load_image through the OpenImageIO plugin), then what passlab does with a loaded
// image before it reaches the GPU: the display copy reports show, and the comparisons a golden
// goes through (diff, heat map, SSIM). The file is named by its magic bytes (PNG, JPEG, EXR,
// Radiance HDR, TIFF; anything else .png), as users name their files. Seeds: the repository's
// goldens and assets (.png, .exr under 2 MB) and tests/fuzz/seeds/image.
#include "fuzz_input.hpp"

#include "image/compare.hpp"
#include "image/image.hpp"

#include <cstring>

namespace {

const char* extension_for(std::string_view b) {
    if (b.size() >= 4 && std::memcmp(b.data(), "\x89PNG", 4) == 0) return ".png";
    if (b.size() >= 2 && std::memcmp(b.data(), "\xff\xd8", 2) == 0) return ".jpg";
    if (b.size() >= 4 && std::memcmp(b.data(), "\x76\x2f\x31\x01", 4) == 0) return ".exr";
    if (b.size() >= 2 && std::memcmp(b.data(), "#?", 2) == 0) return ".hdr";
    if (b.size() >= 4 && (std::memcmp(b.data(), "II*", 4) == 0 || std::memcmp(b.data(), "MM\0*", 4) == 0)) return ".tif";
    return ".png";
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    // campaign.sh gives each target 2 GB: an image that needs more to decode is refused by the
    // same check that refuses one larger than the machine's free memory.
    static const bool limited = (pl::image::set_decode_limit(1ull << 30), true);
    (void)limited;
    const auto bytes = pl::fuzz::as_text(data, size);
    const auto file = pl::fuzz::write_scratch(std::string("image") + extension_for(bytes), bytes);
    auto img = pl::image::load_image(file);
    if (!img) {
        (void)img.error().format();
        return 0;
    }
    bool tone_mapped = false;
    (void)pl::image::display_copy(*img, &tone_mapped);
    (void)pl::image::diff(*img, *img, 0.01f);
    (void)pl::image::diff_heatmap(*img, *img);
    if (img->width * img->height <= 512 * 512) (void)pl::image::ssim(*img, *img);
    return 0;
}
