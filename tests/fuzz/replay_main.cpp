// The fuzz targets without libFuzzer: runs LLVMFuzzerTestOneInput once per file named on the
// command line (folders are walked recursively, filtered by --ext; a folder after --all gives
// every file, as libFuzzer names its findings crash-SHA1 with no extension), so the ordinary gcc build
// replays the seed corpus and every input a campaign found as a ctest entry. A crash or a
// sanitizer report fails the entry; so does an empty corpus (a replay that ran nothing proves
// nothing).
#include "fuzz_input.hpp"

#include <cstdio>
#include <fstream>
#include <iterator>
#include <string>
#include <system_error>
#include <vector>

namespace fs = std::filesystem;

int main(int argc, char** argv) {
    std::vector<std::string> exts;
    std::vector<fs::path> files;
    for (int i = 1; i < argc; ++i) {
        std::string a = argv[i];
        if (a == "--ext" && i + 1 < argc) { exts.push_back(argv[++i]); continue; }
        bool all = false;
        if (a == "--all" && i + 1 < argc) { all = true; a = argv[++i]; }
        std::error_code ec;
        if (fs::is_directory(a, ec)) {
            for (auto it = fs::recursive_directory_iterator(a, fs::directory_options::skip_permission_denied, ec);
                 !ec && it != fs::recursive_directory_iterator(); it.increment(ec)) {
                if (!it->is_regular_file(ec)) continue;
                const auto ext = it->path().extension().string();
                bool wanted = all || exts.empty();
                for (const auto& e : exts) wanted = wanted || ext == e;
                if (wanted) files.push_back(it->path());
            }
        } else if (fs::is_regular_file(a, ec)) {
            files.push_back(a);
        } else {
            std::fprintf(stderr, "replay: %s: no such file or folder\n", a.c_str());
            return 2;
        }
    }
    if (files.empty()) {
        std::fprintf(stderr, "replay: no inputs (give files or folders; --ext .toml filters folders)\n");
        return 2;
    }
    for (const auto& f : files) {
        std::ifstream in(f, std::ios::binary);
        std::string bytes((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
        // Printed before the run so that a crash names its input.
        std::fprintf(stderr, "replay: %s (%zu bytes)\n", f.c_str(), bytes.size());
        LLVMFuzzerTestOneInput(reinterpret_cast<const uint8_t*>(bytes.data()), bytes.size());
    }
    std::printf("replay: %zu inputs ran without a crash\n", files.size());
    return 0;
}
