// Checks a parsed graph before anything is compiled or allocated: names, references, formats,
// pass kinds, shader files, evaluated sizes and memory, test cases. Each error points at the
// offending value (file:line:col), names the pass and the resource, and suggests the nearest
// valid name with the list of valid ones in its notes.
#pragma once

#include "graph/desc.hpp"
#include "graph/sizeexpr.hpp"

#include <array>
#include <optional>

namespace pl::graph {

struct ValidateOptions {
    // Shader lookup order. Empty: the preset folder, then the repository's passes/.
    std::vector<std::filesystem::path> search_dirs;
    // Evaluate sizes at this view size (--size) instead of [view].size.
    std::optional<std::array<int, 2>> view_size;
    // Also evaluate every size at each [[test]]'s size and param overrides, so a test that would
    // make "view/64" zero fails here rather than in the middle of `passlab test`.
    bool per_test_sizes = true;
    // Also check what each test reads (levels, layers, probe texels, buffer elements) at its size
    // and overrides. Off for a build whose view size or params were overridden (one test case's
    // own build, render --size): there [view].size and the param defaults are no longer known,
    // and the plain build of `check` and of `test` has already judged every case.
    bool test_reads = true;
};

Status validate_graph(const GraphDesc& g, const ValidateOptions& opt);
// The same, then fills g.output with default_output(g) when [output] was absent.
Status validate_graph(GraphDesc& g, const ValidateOptions& opt);

// A host-built buffer (generator = "bvh" | "triangles") is sized by its build, so its size is
// bounded when it is built, against the same limit as a `size` (error at its generator key).
Status check_built_buffer_size(const BufferDesc& b, int64_t bytes);

// The image shown and written when there is no [output]: walking the enabled passes from the
// last, the first colour target of a raster pass (its resolve image when it has one) or the dst
// image of a blit/copy; if no pass writes one (compute-only graphs), the last declared image
// with a colour format. Empty when the graph has no colour image at all.
std::string default_output(const GraphDesc& g);

// The repository's pass library: $PASSLAB_ROOT/passes, else PASSLAB_SOURCE_DIR/passes.
std::filesystem::path passes_dir();
// The preset folder, then passes_dir().
std::vector<std::filesystem::path> default_search_dirs(const GraphDesc& g);

// Where shader `file` (as written in preset.toml) is found: the first of `search` holding it
// (default_search_dirs(g) when `search` is empty); empty path when none does.
std::filesystem::path resolve_shader_path(const GraphDesc& g, const std::string& file,
                                          const std::vector<std::filesystem::path>& search);
std::filesystem::path resolve_shader_path(const std::string& file, const std::vector<std::filesystem::path>& search);

// The format an image ends up with: its own `format` when written; for file and generator images
// without one, rgba32f for .exr/.hdr files and rgba8_srgb when srgb; an alias's target's format.
std::string effective_format(const GraphDesc& g, const ImageDesc& d);

} // namespace pl::graph
