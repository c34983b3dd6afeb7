#include "fuzz_input.hpp"

#include <fstream>
#include <string>
#include <unistd.h>

namespace pl::fuzz {

std::filesystem::path scratch_dir() {
    static const std::filesystem::path dir = [] {
        auto d = std::filesystem::temp_directory_path() / ("passlab-fuzz-" + std::to_string(::getpid()));
        std::filesystem::create_directories(d);
        return d;
    }();
    return dir;
}

std::filesystem::path write_scratch(const std::string& name, std::string_view bytes) {
    auto p = scratch_dir() / name;
    std::ofstream(p, std::ios::binary | std::ios::trunc).write(bytes.data(), std::streamsize(bytes.size()));
    return p;
}

} // namespace pl::fuzz
