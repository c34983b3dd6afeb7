// Fuzz target: the host's own SPIR-V reader. Every module passlab binds goes through it: the
// reflector (bindings by name, push-constant and block sizes, the compute local size), the
// private/workgroup memory guards, and the cross-stage binding rewrite. Its input is normally
// glslang's output, but the SPIR-V cache (~/.cache/passlab/spirv) is a file on disk that a full
// disk, a crash mid-write or another version can leave in any state, so no word sequence may
// crash it. The input's bytes are the module's words (little-endian, a trailing partial word
// dropped); the stage is the first OpEntryPoint's execution model, fragment when there is none.
// Seeds: tests/fuzz/seeds/spirv, modules written by `passlab check --spirv` (see README.md there).
#include "fuzz_input.hpp"

#include "shader/bindings.hpp"
#include "shader/program.hpp"

#include <cstring>

namespace {

pl::shader::Stage entry_stage(const std::vector<uint32_t>& w) {
    for (size_t i = 5; i < w.size();) {
        const uint32_t op = w[i] & 0xffff, len = w[i] >> 16;
        if (len == 0 || i + len > w.size()) break;
        if (op == 15 && len >= 2 && w[i + 1] <= 5) return static_cast<pl::shader::Stage>(w[i + 1]);  // OpEntryPoint
        i += len;
    }
    return pl::shader::Stage::fragment;
}

} // namespace

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    std::vector<uint32_t> words(size / 4);
    if (!words.empty()) std::memcpy(words.data(), data, words.size() * 4);
    const auto stage = entry_stage(words);
    auto r = pl::shader::reflect_spirv(words, stage);
    if (!r) (void)r.error().format();
    (void)pl::shader::private_memory_bytes(words);
    (void)pl::shader::workgroup_memory_bytes(words);
    // Two stages of one pass, as a vertex + fragment program would give them.
    std::vector<pl::shader::StageSpirv> stages{{pl::shader::Stage::vertex, words}, {stage, words}};
    pl::shader::unify_bindings(stages);
    return 0;
}
