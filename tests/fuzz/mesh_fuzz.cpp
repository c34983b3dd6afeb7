// Fuzz target: mesh files as a preset's `mesh = "FILE"` reads them (.obj through tinyobjloader,
// .gltf through tinygltf: JSON content is named .gltf), then the derived data every mesh gets
// (tangents, bounds, welding, adjacency). Seeds: the repository's .obj and .gltf files.
#include "fuzz_input.hpp"

#include "scene/mesh.hpp"

extern "C" int LLVMFuzzerTestOneInput(const uint8_t* data, size_t size) {
    const auto text = pl::fuzz::as_text(data, size);
    const bool gltf = !text.empty() && text[0] == '{';
    const auto file = pl::fuzz::write_scratch(gltf ? "mesh.gltf" : "mesh.obj", text);
    auto m = pl::scene::load_mesh(file);
    if (!m) {
        (void)m.error().format();
        return 0;
    }
    pl::scene::compute_tangents(*m);
    pl::scene::compute_bounds(*m);
    (void)pl::scene::weld_positions(*m);
    (void)pl::scene::adjacency_indices(*m);
    return 0;
}
