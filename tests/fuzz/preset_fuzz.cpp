// Fuzz target: a preset.toml, read and checked as `passlab check` does (parse, then validate
// against the repository's passes/), with every error formatted as the CLI prints it. Seeds:
// every preset.toml in the repository and the bad-input cases of tests/bad.
#include "fuzz_input.hpp"

#include "graph/parse.hpp"
#include "graph/validate.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto file = pl::fuzz::write_scratch("preset.toml", pl::fuzz::as_text(data, size));
    auto g = pl::graph::parse_graph_file(file);
    if (!g) {
        (void)g.error().format();
        return 0;
    }
    pl::graph::ValidateOptions opt;  // the preset folder, then passes/: as `check` does
    auto s = pl::graph::validate_graph(*g, opt);
    if (!s) (void)s.error().format();
    return 0;
}
