// Device-free half of loading a preset: parse + validate the graph, compile every pass's
// shaders with the injected preamble, resolve shader resource names to graph images/buffers,
// derive each pass's reads/writes and the execution order. `passlab check` stops here.
#pragma once

#include "exec/params.hpp"
#include "exec/plan.hpp"
#include "graph/desc.hpp"
#include "shader/program.hpp"

#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pl::exec {

struct BuildOptions {
    std::optional<std::array<int, 2>> size;  // overrides [view].size
    std::vector<std::string> set;            // "name=value" param overrides
    std::map<std::string, graph::Value> set_values;  // same, from a test case
    std::map<std::string, graph::CameraDesc> cameras;  // a test case's camera overrides (replace by name)
    std::filesystem::path cache_dir;         // SPIR-V cache; empty = none
    // Folders searched before the preset's own for shader files (exercise overlays).
    std::vector<std::filesystem::path> overlay_dirs;
};

// What a shader binding is bound to.
struct BoundResource {
    enum class Kind { frame, params, image, image_prev, buffer, buffer_prev, cameras };
    shader::Binding binding;
    Kind kind = Kind::image;
    std::string resource;  // graph image/buffer name (for *_prev: the history image's name)
    Access access = Access::sampled;
    const graph::ViewRef* view = nullptr;  // bind = { name = { image, mip, layer } }: one level/layer
};

// The level and layer a use of an image selects in one run of a pass: -1 = every level / layer.
struct Sel {
    int mip = -1, layer = -1;
};

// The selections of one run: per colour target, the depth attachment, and per binding (parallel
// to CompiledPass::bindings).
struct RunViews {
    std::vector<Sel> targets;
    Sel depth;
    std::vector<Sel> bindings;
};

struct CompiledPass {
    const graph::PassDesc* desc = nullptr;  // points into CompiledGraph::desc
    shader::Program program;                // empty for transfer kinds
    std::vector<BoundResource> bindings;
    graph::PassIO io;                       // names read / written (for the planner and dot)
    int repeat = 1;                         // its own repeat
    int group = -1;                         // index into CompiledGraph::groups, -1 = none
    // Per run (group_iteration * repeat + iteration): mip/layer expressions evaluated and
    // checked at build time (exec/views.cpp), so recording only looks them up.
    std::vector<RunViews> runs;
};

// A [[group]]: members (indices into passes) recorded in the listed order `repeat` times.
struct CompiledGroup {
    const graph::GroupDesc* desc = nullptr;
    int repeat = 1;
    std::vector<size_t> members;
};

struct CompiledGraph {
    graph::GraphDesc desc;
    std::array<int, 2> view{640, 360};
    ParamLayout param_layout;
    std::vector<CompiledPass> passes;  // same order as desc.passes
    std::vector<CompiledGroup> groups;  // same order as desc.groups
    // Execution order (indices into passes); a group's members are contiguous, in listed order.
    std::vector<size_t> order;
    std::vector<std::filesystem::path> dependencies;  // every file read (toml, shaders, includes, images)
    std::vector<std::filesystem::path> search_dirs;   // shader lookup: overlays, preset, passes/
};

// The whole device-free pipeline. Errors carry file:line:col, pass and resource.
Result<CompiledGraph> build_graph(const std::filesystem::path& preset_toml, const BuildOptions& opt);

// Finds `preset.toml` for a PRESET argument: a folder holding it, a .toml file, or a preset name
// as listed by `passlab list` (family/name or just name) under presets/.
Result<std::filesystem::path> resolve_preset(const std::string& arg);

// The repository's passes/ library and presets/ folder.
std::filesystem::path passes_dir();
std::filesystem::path presets_dir();

} // namespace pl::exec
