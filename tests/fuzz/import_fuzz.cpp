// Fuzz target: the Shadertoy/ISF importer. The content picks the source form as a user's file
// name would (JSON when it starts with '{' or '[', ISF when it holds a /*{ header, else a
// mainImage file), so the seeds are the repository's files as they are. An accepted source's generated preset.toml
// is parsed back, since the importer must only ever write presets passlab can read.
// Seeds: tests/import.
#include "fuzz_input.hpp"

#include "graph/parse.hpp"
#include "import/import.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto text = pl::fuzz::as_text(data, size);
    const char* name = "toy.glsl";
    if (!text.empty() && (text[0] == '{' || text[0] == '[')) name = "toy.json";
    else if (text.find("/*{") != std::string_view::npos) name = "toy.fs";
    const auto file = pl::fuzz::write_scratch(name, text);
    auto p = pl::import::import_source(file, {});
    if (!p) {
        (void)p.error().format();
        return 0;
    }
    if (auto it = p->files.find("preset.toml"); it != p->files.end()) {
        auto g = pl::graph::parse_graph_text(it->second, pl::fuzz::scratch_dir() / "import" / "preset.toml");
        if (!g) (void)g.error().format();
    }
    return 0;
}
