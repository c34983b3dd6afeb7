// Fuzz target: one shader through the host's compile path (include expansion with passes/ as
// the include folder, glslang, the log parser that maps errors back to file:line:col, SPIR-V
// reflection and the memory checks). A source that declares local_size is compiled as a compute
// shader, anything else as a fragment shader. Seeds: every .frag/.comp/.glsl in the repository.
#include "fuzz_input.hpp"

#include "graph/validate.hpp"
#include "shader/program.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto text = pl::fuzz::as_text(data, size);
    const bool compute = text.find("local_size") != std::string_view::npos;
    const auto file = pl::fuzz::write_scratch(compute ? "main.comp" : "main.frag", text);
    pl::shader::CompileOptions opt;
    opt.include_dirs = {pl::graph::passes_dir()};
    pl::shader::StageInput in{compute ? pl::shader::Stage::compute : pl::shader::Stage::fragment, file, "main", {}};
    auto p = pl::shader::compile_program({in}, opt);
    if (!p) (void)p.error().format();
    return 0;
}
