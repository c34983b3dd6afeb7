#include "util/paths.hpp"

namespace fs = std::filesystem;

namespace pl {

std::optional<fs::path> path_within(const fs::path& p, const fs::path& dir) {
    auto rel = canonical_or_normal(p).lexically_relative(canonical_or_normal(dir));
    if (rel.empty() || rel == "." || *rel.begin() == "..") return std::nullopt;
    return rel;
}

fs::path canonical_or_normal(const fs::path& p) {
    std::error_code ec;
    fs::path c = fs::weakly_canonical(p, ec);
    if (!ec) return c;
    fs::path a = fs::absolute(p, ec);
    return (ec ? p : a).lexically_normal();
}

bool is_shader_file(const std::filesystem::path& p) {
    static const char* const kExt[] = {".frag", ".vert", ".comp", ".geom", ".tesc", ".tese", ".glsl", ".fs", ".vs"};
    const auto ext = p.extension();
    for (const char* e : kExt)
        if (ext == e) return true;
    return false;
}

} // namespace pl
