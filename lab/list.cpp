// `passlab list`: every presets/<family>/<name>/preset.toml with its title and summary.
#include "verbs.hpp"

#include "exec/build.hpp"
#include "graph/parse.hpp"

#include <algorithm>
#include <cstdio>
#include <filesystem>

namespace fs = std::filesystem;

namespace pl::lab {

int list(bool verbose) {
    fs::path root = exec::presets_dir();
    std::vector<fs::path> found;
    std::error_code ec;
    if (fs::is_directory(root, ec))
        for (const auto& e : fs::recursive_directory_iterator(root, ec))
            if (e.path().filename() == "preset.toml") found.push_back(e.path());
    std::sort(found.begin(), found.end());
    int broken = 0;
    for (const auto& f : found) {
        std::string name = fs::relative(f.parent_path(), root).string();
        auto g = graph::parse_graph_file(f);
        if (!g) {
            ++broken;
            std::printf("%-40s (cannot be parsed: %s)\n", name.c_str(), g.error().message.c_str());
            continue;
        }
        std::printf("%-40s %s — %s\n", name.c_str(), g->meta.title.c_str(), g->meta.summary.c_str());
        if (verbose) std::printf("%-40s %s\n", "", f.parent_path().string().c_str());
    }
    std::fprintf(stderr, "%zu preset(s) in %s\n", found.size(), root.string().c_str());
    return broken ? 1 : 0;
}

} // namespace pl::lab
