// `passlab import SRC -o DEST`: a Shadertoy or ISF source as an ordinary preset folder
// (preset.toml, one file per tab or pass, the generated wrappers). Never overwrites.
#include "verbs.hpp"

#include "import/import.hpp"

#include <cstdio>

namespace pl::lab {

int import_source(const ImportVerbOptions& o) {
    import::ImportOptions io;
    io.kind = o.kind;
    io.golden = o.golden;
    auto files = import::import_source(o.source, io);
    if (!files) return report(files.error());
    for (const auto& w : files->warnings) std::fprintf(stderr, "import: warning: %s\n", w.c_str());
    if (auto s = import::write_preset(*files, o.dest, false); !s) return report(s.error());
    for (const auto& [name, text] : files->files) std::printf("%s/%s\n", o.dest.c_str(), name.c_str());
    for (const auto& [name, from] : files->copies) std::printf("%s/%s\n", o.dest.c_str(), name.c_str());
    std::fprintf(stderr, "import: wrote %s; `passlab run %s` shows it, `passlab test %s` records its golden\n", o.dest.c_str(),
                 o.dest.c_str(), o.dest.c_str());
    return 0;
}

} // namespace pl::lab
