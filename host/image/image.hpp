// CPU images: always RGBA float32 in memory (linear for HDR, as stored for LDR), so comparison,
// probes and file I/O share one representation. Files go through OpenImageIO.
#pragma once

#include "util/error.hpp"

#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace pl::image {

struct Image {
    int width = 0, height = 0, depth = 1;  // depth > 1 for 3D generators
    std::vector<float> pixels;             // RGBA float, row-major, width*height*depth*4
    float* at(int x, int y, int z = 0) { return &pixels[(((size_t)z * height + y) * width + x) * 4]; }
    const float* at(int x, int y, int z = 0) const {
        return &pixels[(((size_t)z * height + y) * width + x) * 4];
    }
};

// Loads PNG/JPG/EXR/HDR... as RGBA float. 8-bit files give values in [0,1] as stored (sRGB
// encoded if the file is); callers decide about sRGB through the upload format.
Result<Image> load_image(const std::filesystem::path& file);
// Caps the memory load_image may need to decode one file (default: the system's MemAvailable,
// read at each load); 0 restores the default. For tests and the fuzz target.
void set_decode_limit(unsigned long long bytes);

// Writes by extension: .png -> 8-bit RGBA (values clamped to [0,1], stored as given, no
// conversion), .exr -> half or float RGBA. `png_compression` 1..9 (1 is fast: snapshots).
struct SaveOptions {
    bool exr_half = true;
    int png_compression = 1;
};
Status save_image(const Image& img, const std::filesystem::path& file, const SaveOptions& = {});

// Procedural textures so presets need no downloaded assets. Names: checker, uv-grid,
// value-noise, gradient-noise, constant. Args (all optional): cells (checker/grid count),
// color_a, color_b (RGBA), frequency, octaves, seed, value (constant colour).
std::vector<std::string> generator_names();
Result<Image> generate_image(const std::string& generator, int width, int height, int depth,
                             const std::map<std::string, std::vector<double>>& args);

// An image for a person to look at as 8-bit: as stored when it lies in [0, 1]; otherwise (HDR,
// negative values) each channel through x / (1 + |x|) sign-kept, then the sRGB curve, and
// `*tone_mapped` says so. Reports use it for the images checks read.
Image display_copy(const Image& img, bool* tone_mapped);

// Colour helpers.
float srgb_to_linear(float c);
float linear_to_srgb(float c);

} // namespace pl::image
