// What the fuzz targets share: libFuzzer's entry point, and a scratch folder for the targets whose
// code under test reads files (the importer, the mesh loader), since passlab reads user content
// from disk and the file path is part of what it reports.
#pragma once

#include <cstddef>
#include <cstdint>
#include <filesystem>
#include <string_view>

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size);

namespace pl::fuzz {

inline std::string_view as_text(const uint8_t* data, size_t size) {
    return {reinterpret_cast<const char*>(data), size};
}

// A per-process scratch folder (created once), so two campaigns on one machine do not collide.
std::filesystem::path scratch_dir();
// Writes `bytes` to scratch_dir()/name and returns the path.
std::filesystem::path write_scratch(const std::string& name, std::string_view bytes);

} // namespace pl::fuzz
