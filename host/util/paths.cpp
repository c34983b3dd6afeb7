#include "util/paths.hpp"

namespace fs = std::filesystem;

namespace pl {

std::optional<fs::path> path_within(const fs::path& p, const fs::path& dir) {
    auto rel = fs::weakly_canonical(p).lexically_relative(fs::weakly_canonical(dir));
    if (rel.empty() || rel == "." || *rel.begin() == "..") return std::nullopt;
    return rel;
}

} // namespace pl
