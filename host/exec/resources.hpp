// The GPU side of a graph's [images], [buffers] and [meshes]: created once from the description
// (sizes evaluated, formats checked against the device), uploaded from files and generators, and
// each with the ResourceState the planner's transition() tracks across passes and frames.
#pragma once

#include "exec/build.hpp"
#include "exec/plan.hpp"
#include "scene/simplify.hpp"
#include "vk/formats.hpp"
#include "vk/resources.hpp"

#include <array>
#include <map>
#include <memory>
#include <optional>
#include <string>

namespace pl::exec {

struct PhysImage {
    vk::Image image;
    ImageState state;  // per mip level and layer
    VkImageView storage_view = VK_NULL_HANDLE;  // mip 0, all layers, for imageLoad/Store
    vk::UniqueImageView storage_view_owner;
    // The subresources of one level and/or layer (Vulkan tracks 3D slices with their level).
    SubRange range(int mip, int layer) const {
        SubRange r = state.all();
        if (mip >= 0) r.mip = static_cast<uint32_t>(mip), r.mips = 1;
        if (layer >= 0 && image.info().type != VK_IMAGE_TYPE_3D) r.layer = static_cast<uint32_t>(layer), r.layers = 1;
        return r;
    }
};

struct GraphImage {
    const graph::ImageDesc* desc = nullptr;
    const vk::FormatInfo* format = nullptr;
    VkExtent3D extent{1, 1, 1};
    uint32_t mips = 1, layers = 1;
    // History images own two physical images, swapped every frame; aliases point at another's.
    std::array<std::shared_ptr<PhysImage>, 2> phys;
    vk::UniqueSampler sampler;
    bool history = false;
};

struct PhysBuffer {
    vk::Buffer buffer;
    ResourceState state;
};

struct GraphBuffer {
    const graph::BufferDesc* desc = nullptr;
    std::array<std::shared_ptr<PhysBuffer>, 2> phys;
    bool history = false;
};

struct GpuMesh {
    vk::Buffer vertices, indices;
    uint32_t index_count = 0;
    // For passes with topology = "triangles_adjacency" (made only when one uses the mesh).
    vk::Buffer adjacency;
    uint32_t adjacency_count = 0;
    uint32_t instances = 1;
    // simplify = { morph = ... }: vertex binding 1, one scene::MorphVertex per vertex.
    vk::Buffer morph;
    bool has_morph = false;
    std::optional<scene::SimplifyStats> simplified;
    double simplify_ms = 0;
};

struct GraphResources {
    std::map<std::string, GraphImage> images;
    std::map<std::string, GraphBuffer> buffers;
    std::map<std::string, GpuMesh> meshes;
};

// "no image named 'x' in the graph" (kind = "image" or "buffer") with the nearest names of `m`.
template <class Map> Error no_resource(const char* kind, const std::string& name, const Map& m) {
    std::vector<std::string> names;
    for (const auto& [n, r] : m) names.push_back(n);
    Error e = make_error(std::string("no ") + kind + " named '" + name + "' in the graph");
    e.resource = name;
    suggest(e, name, names, std::string(kind) + "s");
    return e;
}

// Creates and uploads everything. Errors (unsupported format usage on this device, unreadable
// image file, bad mesh) name the resource and its line in preset.toml.
Result<GraphResources> create_resources(vk::Context& ctx, const CompiledGraph& g);

} // namespace pl::exec
