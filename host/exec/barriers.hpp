// Turning the planner's Barrier values into vkCmdPipelineBarrier2 calls, and the one place that
// walks a mip chain (used by uploads and by the `mips` pass kind): per-level states, still
// derived with transition().
#pragma once

#include "exec/plan.hpp"
#include "exec/resources.hpp"

#include <vector>

namespace pl::exec {

struct BarrierBatch {
    std::vector<VkImageMemoryBarrier2> images;
    std::vector<VkBufferMemoryBarrier2> buffers;

    void add(const Barrier& b, VkImage image, const VkImageSubresourceRange& range);
    void add(const Barrier& b, VkBuffer buffer);
    void flush(VkCommandBuffer cb);  // records one vkCmdPipelineBarrier2 and empties the batch
};

// Brings `range` of `img` (default: all of it) to the state `usage` needs, adding the derived
// barriers (one per rectangle of subresources in the same state; none where nothing changes).
void require(BarrierBatch& batch, PhysImage& img, const Usage& usage, bool discard = false);
void require(BarrierBatch& batch, PhysImage& img, const SubRange& range, const Usage& usage, bool discard = false);
void require(BarrierBatch& batch, PhysBuffer& buf, const Usage& usage);

// Makes transfer writes visible to host reads after the submission's fence (readbacks).
void transfer_to_host(VkCommandBuffer cb);

// Fills mips 1..n-1 of `img` from mip 0 by successive linear 2:1 blits (a box filter for
// power-of-two sizes). Leaves every level in the state `final_usage` asks for.
void record_mip_chain(VkCommandBuffer cb, PhysImage& img, const Usage& final_usage);

} // namespace pl::exec
