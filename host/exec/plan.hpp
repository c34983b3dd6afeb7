// The planner: orders passes from what they read and write, and derives every barrier and
// layout transition from declared uses. Pure data (no device), so it is unit-tested directly;
// the executor calls transition() for each resource a pass touches, and no pass kind writes a
// barrier by hand.
#pragma once

#include "util/error.hpp"

#include <vulkan/vulkan.h>

#include <optional>
#include <tuple>
#include <string>
#include <vector>

namespace pl::exec {

// How a pass uses a resource.
enum class Access {
    sampled,            // texture() in a shader
    storage_read,       // readonly image/buffer
    storage_write,      // writeonly image/buffer
    storage_read_write, // image/buffer with both (atomics, in-place)
    uniform_read,       // uniform buffer
    color_attachment,   // render target (written)
    depth_attachment,   // depth/stencil target written (and tested)
    depth_read,         // depth test without writes
    resolve_dst,        // MSAA resolve target
    transfer_src,
    transfer_dst,
    indirect_read,      // draw/dispatch arguments
    vertex_read,        // vertex/index buffer
};

struct Usage {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;  // ignored for buffers
    VkPipelineStageFlags2 stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 access = VK_ACCESS_2_NONE;
    bool write = false;
};

// `shader_stages` are the pipeline stages of the shaders using a sampled/storage/uniform
// resource (ignored for attachment and transfer uses).
Usage usage_of(Access a, VkPipelineStageFlags2 shader_stages);
// Two uses of one resource in the same pass combine into one (a storage image both sampled and
// written needs GENERAL).
Usage merge(const Usage& a, const Usage& b);

// What the GPU last did with a resource, tracked across passes and frames.
struct ResourceState {
    VkImageLayout layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 write_stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 write_access = VK_ACCESS_2_NONE;
    VkPipelineStageFlags2 read_stages = VK_PIPELINE_STAGE_2_NONE;  // reads since the last write
    VkPipelineStageFlags2 visible_stages = VK_PIPELINE_STAGE_2_NONE;  // ... that saw the write
    VkAccessFlags2 visible_access = VK_ACCESS_2_NONE;
};

struct Barrier {
    VkImageLayout old_layout = VK_IMAGE_LAYOUT_UNDEFINED, new_layout = VK_IMAGE_LAYOUT_UNDEFINED;
    VkPipelineStageFlags2 src_stages = VK_PIPELINE_STAGE_2_NONE, dst_stages = VK_PIPELINE_STAGE_2_NONE;
    VkAccessFlags2 src_access = VK_ACCESS_2_NONE, dst_access = VK_ACCESS_2_NONE;
    bool operator==(const Barrier&) const = default;
};

// The barrier needed before `next` (nullopt when none is: a read after a read in the same
// layout, or a read already made visible), and the state after it. `discard` allows the old
// contents to be dropped (layout UNDEFINED as source: a full clear or first use).
std::optional<Barrier> transition(ResourceState& state, const Usage& next, bool discard = false);

// Mip levels [mip, mip + mips) x array layers [layer, layer + layers) of an image.
struct SubRange {
    uint32_t mip = 0, mips = 1, layer = 0, layers = 1;
    bool overlaps(const SubRange& o) const {
        return mip < o.mip + o.mips && o.mip < mip + mips && layer < o.layer + o.layers && o.layer < layer + layers;
    }
    bool operator==(const SubRange&) const = default;
    bool operator<(const SubRange& o) const {
        return std::tie(mip, mips, layer, layers) < std::tie(o.mip, o.mips, o.layer, o.layers);
    }
};

// An image's state per subresource (mip level x layer): a pass that reads level i and writes
// level i + 1 moves only those levels, so the other levels keep their layout and need no barrier.
struct ImageState {
    uint32_t mips = 1, layers = 1;
    std::vector<ResourceState> sub;  // mip-major: sub[mip * layers + layer]
    ImageState() : sub(1) {}
    ImageState(uint32_t m, uint32_t l) : mips(m), layers(l), sub(size_t(m) * l) {}
    ResourceState& at(uint32_t mip, uint32_t layer) { return sub[size_t(mip) * layers + layer]; }
    const ResourceState& at(uint32_t mip, uint32_t layer) const { return sub[size_t(mip) * layers + layer]; }
    SubRange all() const { return {0, mips, 0, layers}; }
    // The layout of a range every subresource of which is in one layout (after a transition).
    VkImageLayout layout(const SubRange& r) const { return at(r.mip, r.layer).layout; }
};

struct RangeBarrier {
    Barrier barrier;
    SubRange range;
};

// transition() for every subresource of `range`. Subresources that need the same barrier are
// merged into rectangles (runs of layers, then runs of levels with the same runs), so an image
// in one state yields one barrier over the range and only what differs is split.
std::vector<RangeBarrier> transition(ImageState& state, const SubRange& range, const Usage& next, bool discard = false);

// One pass as the planner sees it: resource names read and written, in declaration order.
struct PlanPass {
    std::string name;
    SourceLoc loc;
    std::vector<std::string> reads, writes;
    bool group = false;  // a [[group]] planned as one unit (messages say "group 'name'")
};

// Execution order. Passes run in file order unless a pass reads what a later-declared pass
// writes (and nothing earlier writes it): then the writer moves first. A reader waits for the
// last writer declared before it, a writer for the readers before it (write-after-read), writers
// of one resource keep their order. A cycle is an error naming the chain of passes and resources.
Result<std::vector<size_t>> order_passes(const std::vector<PlanPass>& passes);

} // namespace pl::exec
