// Public API of host/shader: turn the GLSL files of one pass into SPIR-V plus a merged reflection,
// with errors that point at the user's file:line:col through includes.
// Implemented by include.cpp (include expansion, #line mapping, BOM, cycles), compile.cpp (glslang),
// reflect.cpp (SPIR-V reflection + private-memory guard), cache.cpp (content-hash SPIR-V cache).
#pragma once

#include "util/error.hpp"

#include <cstdint>
#include <filesystem>
#include <map>
#include <string>
#include <vector>

namespace pl::shader {

enum class Stage { vertex, tess_control, tess_eval, geometry, fragment, compute };
const char* stage_name(Stage s);  // "vertex", ...

// What a descriptor binding is, as the executor needs to know to bind it.
enum class BindingType {
    uniform_buffer,          // uniform block
    storage_buffer,          // buffer block
    combined_image_sampler,  // sampler2D, samplerCube, sampler2DShadow ...
    sampled_image,           // texture2D (separate)
    storage_image,           // image2D ...
    sampler,                 // sampler (separate)
};

enum class ImageDim { none, d1, d2, d3, cube, buffer };

struct Binding {
    std::string name;  // variable name; for blocks the instance name if any, else the block name
    std::string block_name;  // for blocks: the block type name ("" otherwise)
    uint32_t set = 0, binding = 0;
    BindingType type = BindingType::uniform_buffer;
    ImageDim dim = ImageDim::none;
    bool arrayed = false;       // sampler2DArray etc
    bool multisampled = false;
    bool shadow = false;        // depth-comparison sampler
    bool is_integer = false;    // isampler/usampler, iimage/uimage
    uint32_t count = 1;         // array size (1 if not an array)
    uint32_t block_size = 0;    // bytes, for blocks (runtime arrays count as 0 elements)
    std::string storage_format; // storage images: GLSL format qualifier name ("rgba16f"), "" if none
    bool non_writable = false;  // readonly
    bool non_readable = false;  // writeonly
    uint32_t stages = 0;        // bit (1 << Stage)
};

struct Reflection {
    std::vector<Binding> bindings;       // merged across stages, sorted by (set, binding)
    uint32_t push_constant_size = 0;     // bytes, max over stages
    uint32_t push_constant_stages = 0;   // bit (1 << Stage)
    uint32_t local_size[3] = {1, 1, 1};  // compute only
    std::vector<uint32_t> vertex_input_locations;  // vertex stage inputs (location numbers)
    uint32_t fragment_output_count = 0;  // highest fragment output location + 1
    // Compute only: bytes of `shared` variables, and where the largest is declared (the
    // device's maxComputeSharedMemorySize is checked against it when a pipeline is made).
    uint64_t shared_bytes = 0;
    SourceLoc shared_decl;
    const Binding* find(const std::string& name) const;
};

struct StageInput {
    Stage stage;
    std::filesystem::path file;  // absolute or relative to cwd; the file as the user named it
    std::string display_name;    // how errors name the file (default: file as given)
    std::string source_override; // if non-empty, compile this text instead of reading `file`
};

struct CompileOptions {
    // Where #include "x" is looked up, in order, after the including file's own folder.
    std::vector<std::filesystem::path> include_dirs;
    // Text injected after #version of every stage (frame block, params block, aliases). It must
    // not shift user line numbers: the compiler re-synchronises with #line after it.
    std::string preamble;
    // Extra per-stage preamble, e.g. the fullscreen vertex outputs.
    std::map<Stage, std::string> stage_preamble;
    std::map<std::string, std::string> defines;  // #define NAME VALUE
    // SPIR-V cache folder; empty disables the cache.
    std::filesystem::path cache_dir;
    // Refuse shaders whose private + function-local memory per invocation exceeds this.
    uint64_t max_private_bytes = 64 * 1024;
    // Refuse compute shaders whose `shared` memory exceeds this before any device is asked: no
    // Vulkan device offers more than 64 KiB (the guaranteed minimum is 16 KiB). The device's
    // own limit is checked when the pipeline is created.
    uint64_t max_shared_bytes = 64 * 1024;
};

struct StageSpirv {
    Stage stage;
    std::vector<uint32_t> words;
};

struct Program {
    std::vector<StageSpirv> stages;
    Reflection reflection;
    // Every file read to build this program (stage files and all includes), absolute paths; the
    // reload watcher maps these back to the pass.
    std::vector<std::filesystem::path> dependencies;
    bool from_cache = false;
};

// Compiles and links the stages of one pass together (so auto-mapped bindings agree across
// stages), reflects the result and checks it. Errors carry file:line:col of the user's source
// (through includes), the offending line, and for include cycles the chain in notes.
Result<Program> compile_program(const std::vector<StageInput>& stages, const CompileOptions& opt);

// Reflects one SPIR-V module (used by compile_program and by tests).
Result<Reflection> reflect_spirv(const std::vector<uint32_t>& words, Stage stage);

// Estimated bytes of Private + Function storage per invocation (arrays included).
uint64_t private_memory_bytes(const std::vector<uint32_t>& words);
// Bytes of Workgroup storage (`shared` variables).
uint64_t workgroup_memory_bytes(const std::vector<uint32_t>& words);

} // namespace pl::shader
