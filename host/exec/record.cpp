// Recording of one pass iteration: uses -> barriers (planner), descriptors by name, then the
// pass kind's commands. The only per-kind code in the executor.
#include "exec/barriers.hpp"
#include "exec/bind.hpp"
#include "exec/executor.hpp"
#include "exec/frame_block.hpp"
#include "exec/texels.hpp"
#include "vk/check.hpp"
#include "vk/clear_value.hpp"

#include <algorithm>
#include <cstring>
#include <map>

namespace pl::exec {

namespace {




VkExtent2D mip_extent(const vk::ImageInfo& info, uint32_t mip) {
    return {std::max(1u, info.extent.width >> mip), std::max(1u, info.extent.height >> mip)};
}

} // namespace

// A copy between a buffer and mip 0 of an image (every layer): the buffer holds the texels
// tightly packed row by row, or for a block-compressed image its blocks (BC1: 8 bytes per 4x4
// texels), which is how a compute pass can encode a texture that the sampler then decodes.
Status Executor::record_buffer_image_copy(VkCommandBuffer cb, const graph::PassDesc& pd, PhysBuffer* b, PhysImage* p,
                                          const vk::FormatInfo* f, bool to_image) {
    const std::string& img_name = to_image ? pd.dst : pd.src;
    const auto& info = p->image.info();
    const uint32_t blk = static_cast<uint32_t>(f->block);
    const VkDeviceSize need = VkDeviceSize((info.extent.width + blk - 1) / blk) * ((info.extent.height + blk - 1) / blk) *
                              info.extent.depth * info.layers * static_cast<VkDeviceSize>(f->bytes_per_texel);
    if (b->buffer.size < need)
        return pass_error(pd, "buffer '" + (to_image ? pd.src : pd.dst) + "' has " + std::to_string(b->buffer.size) +
                                  " bytes; image '" + img_name + "' (" + f->name + ") needs " + std::to_string(need));
    VkBufferImageCopy r{.bufferOffset = 0,
                        .bufferRowLength = 0,  // tightly packed
                        .bufferImageHeight = 0,
                        .imageSubresource = {p->image.aspect(), 0, 0, info.layers},
                        .imageOffset = {0, 0, 0},
                        .imageExtent = info.extent};
    if (to_image)
        vkCmdCopyBufferToImage(cb, b->buffer.buffer, p->image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &r);
    else
        vkCmdCopyImageToBuffer(cb, p->image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, b->buffer.buffer, 1, &r);
    return ok_status();
}

Status Executor::record_pass(VkCommandBuffer cb, size_t pass_index, int iter, int group_iter) {
    CompiledGraph& g = *graph_;
    const CompiledPass& cp = g.passes[pass_index];
    const graph::PassDesc& pd = *cp.desc;
    PassPipeline& pp = *pipelines_[pass_index];
    const CompiledGroup* group = cp.group >= 0 ? &g.groups[static_cast<size_t>(cp.group)] : nullptr;
    // Levels and layers of this run, evaluated at build time (exec/views.cpp).
    const RunViews& rv = cp.runs.at(static_cast<size_t>(group_iter) * static_cast<size_t>(cp.repeat) + static_cast<size_t>(iter));

    // Names -> physical resources for this run: ping-pong pairs swap on odd iterations of the
    // pass and, for a group's pairs, on odd iterations of the group (never both: validated).
    auto swap_in = [](const std::vector<std::string>& pairs, int i, const std::string& n) -> std::string {
        if (i % 2 == 0) return n;
        for (size_t k = 0; k + 1 < pairs.size(); k += 2) {
            if (pairs[k] == n) return pairs[k + 1];
            if (pairs[k + 1] == n) return pairs[k];
        }
        return n;
    };
    auto swapped = [&](const std::string& n) -> std::string {
        std::string m = swap_in(pd.swap, iter, n);
        return group ? swap_in(group->desc->swap, group_iter, m) : m;
    };
    auto image = [&](const std::string& n) -> GraphImage& { return res_.images.at(swapped(n)); };
    auto phys_image = [&](const std::string& n, bool prev) {
        int p = prev ? 1 - frame_parity_ : frame_parity_;
        return image(n).phys[static_cast<size_t>(p)].get();
    };
    auto phys_buffer = [&](const std::string& n, bool prev) {
        int p = prev ? 1 - frame_parity_ : frame_parity_;
        return res_.buffers.at(n).phys[static_cast<size_t>(p)].get();
    };

    // 1. Uses of this iteration, per physical image and subresource range; uses of overlapping
    // ranges merge (over their bounding range), disjoint ones (read level i, write level i + 1)
    // stay apart and keep their own layouts.
    struct ImageUse {
        PhysImage* image;
        SubRange range;
        Usage usage;
        bool discard = true;
    };
    std::vector<ImageUse> img_uses;
    std::map<PhysBuffer*, Usage> buf_uses;
    auto use_range = [&](PhysImage* p, SubRange r, Access a, VkPipelineStageFlags2 stages, bool discard) {
        ImageUse next{p, r, usage_of(a, stages), discard};
        for (size_t k = 0; k < img_uses.size();) {
            ImageUse& o = img_uses[k];
            if (o.image != p || !o.range.overlaps(next.range)) {
                ++k;
                continue;
            }
            uint32_t m0 = std::min(o.range.mip, next.range.mip), l0 = std::min(o.range.layer, next.range.layer);
            uint32_t m1 = std::max(o.range.mip + o.range.mips, next.range.mip + next.range.mips);
            uint32_t l1 = std::max(o.range.layer + o.range.layers, next.range.layer + next.range.layers);
            next = {p, {m0, m1 - m0, l0, l1 - l0}, merge(o.usage, next.usage), o.discard && discard && o.range == next.range};
            img_uses.erase(img_uses.begin() + static_cast<long>(k));
            k = 0;  // the grown range may now overlap an earlier use
        }
        img_uses.push_back(next);
    };
    auto use_image = [&](PhysImage* p, Access a, VkPipelineStageFlags2 stages, bool discard) {
        use_range(p, p->state.all(), a, stages, discard);
    };
    auto use_buffer = [&](PhysBuffer* p, Access a, VkPipelineStageFlags2 stages) {
        Usage u = usage_of(a, stages);
        auto [it, fresh] = buf_uses.try_emplace(p, u);
        if (!fresh) it->second = merge(it->second, u);
    };

    for (size_t k = 0; k < cp.bindings.size(); ++k) {
        const BoundResource& b = cp.bindings[k];
        VkPipelineStageFlags2 st = pipeline_stages(b.binding.stages);
        switch (b.kind) {
        case BoundResource::Kind::image:
        case BoundResource::Kind::image_prev: {
            PhysImage* p = phys_image(b.resource, b.kind == BoundResource::Kind::image_prev);
            use_range(p, p->range(rv.bindings[k].mip, rv.bindings[k].layer), b.access, st, false);
            break;
        }
        case BoundResource::Kind::buffer:
        case BoundResource::Kind::buffer_prev:
            use_buffer(phys_buffer(b.resource, b.kind == BoundResource::Kind::buffer_prev), b.access, st);
            break;
        default: break;  // frame/params blocks are written by the host before submission
        }
    }
    for (size_t k = 0; k < pd.targets.size(); ++k) {
        const auto& t = pd.targets[k];
        PhysImage* p = phys_image(t.image, false);
        use_range(p, p->range(rv.targets[k].mip, rv.targets[k].layer), Access::color_attachment, 0, pd.clear.color.has_value());
        if (!t.resolve.empty()) {
            PhysImage* r = phys_image(t.resolve, false);
            use_range(r, r->range(0, rv.targets[k].layer), Access::resolve_dst, 0, true);
        }
    }
    if (pd.depth) {
        const GraphImage& gi = image(pd.depth->target.image);
        bool full_clear = pd.clear.depth && (!gi.format->has_stencil || pd.clear.stencil);
        PhysImage* p = phys_image(pd.depth->target.image, false);
        use_range(p, p->range(rv.depth.mip, rv.depth.layer),
                  pd.depth->write || pd.stencil.enable ? Access::depth_attachment : Access::depth_read, 0, full_clear);
    }
    bool src_is_buffer = !pd.src.empty() && res_.buffers.count(pd.src);
    bool dst_is_buffer = !pd.dst.empty() && res_.buffers.count(pd.dst);
    switch (pd.kind) {
    case graph::PassKind::blit:
    case graph::PassKind::copy:
        if (src_is_buffer) use_buffer(phys_buffer(pd.src, false), Access::transfer_src, 0);
        else use_image(phys_image(pd.src, false), Access::transfer_src, 0, false);
        if (dst_is_buffer) use_buffer(phys_buffer(pd.dst, false), Access::transfer_dst, 0);
        else use_image(phys_image(pd.dst, false), Access::transfer_dst, 0, true);
        break;
    case graph::PassKind::clear:
        if (res_.buffers.count(pd.image)) use_buffer(phys_buffer(pd.image, false), Access::transfer_dst, 0);
        else use_image(phys_image(pd.image, false), Access::transfer_dst, 0, true);
        break;
    default: break;
    }
    if (!pd.indirect.empty()) use_buffer(phys_buffer(pd.indirect, false), Access::indirect_read, 0);

    BarrierBatch batch;
    for (auto& u : img_uses) require(batch, *u.image, u.range, u.usage, u.discard);
    for (auto& [p, u] : buf_uses) require(batch, *p, u);
    batch.flush(cb);

    // 2. Transfer kinds.
    if (pd.kind == graph::PassKind::mips) {
        PhysImage* p = phys_image(pd.image, false);
        VkFormatProperties fp;
        vkGetPhysicalDeviceFormatProperties(ctx_.physical(), p->image.info().format, &fp);
        if (!(fp.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT))
            return pass_error(pd, "image '" + pd.image + "' has a format that cannot be filtered linearly for mips");
        record_mip_chain(cb, *p, usage_of(Access::sampled, VK_PIPELINE_STAGE_2_ALL_GRAPHICS_BIT |
                                                               VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT));
        return ok_status();
    }
    if (pd.kind == graph::PassKind::clear) {
        if (res_.buffers.count(pd.image)) {
            // Validated as an integer in 0..4294967295 (vk::fill_value_problem), so exact.
            uint32_t v = pd.clear.color ? static_cast<uint32_t>((*pd.clear.color)[0]) : 0u;
            vkCmdFillBuffer(cb, phys_buffer(pd.image, false)->buffer.buffer, 0, VK_WHOLE_SIZE, v);
            return ok_status();
        }
        PhysImage* p = phys_image(pd.image, false);
        auto range = p->image.full_range();
        if (p->image.aspect() & VK_IMAGE_ASPECT_DEPTH_BIT) {
            VkClearDepthStencilValue v{pd.clear.depth.value_or(1.0f), pd.clear.stencil.value_or(0)};
            vkCmdClearDepthStencilImage(cb, p->image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &v, 1, &range);
        } else {
            VkClearColorValue v = vk::clear_color(*image(pd.image).format, pd.clear.color.value_or(std::array<double, 4>{}));
            vkCmdClearColorImage(cb, p->image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &v, 1, &range);
        }
        return ok_status();
    }
    if (pd.kind == graph::PassKind::blit || pd.kind == graph::PassKind::copy) {
        if (src_is_buffer && dst_is_buffer) {
            PhysBuffer* s = phys_buffer(pd.src, false);
            PhysBuffer* d = phys_buffer(pd.dst, false);
            VkBufferCopy c{0, 0, std::min(s->buffer.size, d->buffer.size)};
            vkCmdCopyBuffer(cb, s->buffer.buffer, d->buffer.buffer, 1, &c);
            return ok_status();
        }
        if (src_is_buffer || dst_is_buffer)
            return record_buffer_image_copy(cb, pd, phys_buffer(src_is_buffer ? pd.src : pd.dst, false),
                                            phys_image(src_is_buffer ? pd.dst : pd.src, false),
                                            image(src_is_buffer ? pd.dst : pd.src).format, src_is_buffer);
        PhysImage* s = phys_image(pd.src, false);
        PhysImage* d = phys_image(pd.dst, false);
        const auto& si = s->image.info();
        const auto& di = d->image.info();
        uint32_t layers = std::min(si.layers, di.layers);
        if (si.samples != VK_SAMPLE_COUNT_1_BIT) {
            // A multisampled source is resolved, which is what blitting it means.
            VkImageResolve r{.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, layers},
                             .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, layers},
                             .extent = {std::min(si.extent.width, di.extent.width),
                                        std::min(si.extent.height, di.extent.height), 1}};
            vkCmdResolveImage(cb, s->image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, d->image.handle(),
                              VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &r);
        } else if (pd.kind == graph::PassKind::copy) {
            VkImageCopy c{.srcSubresource = {s->image.aspect(), 0, 0, layers},
                          .dstSubresource = {d->image.aspect(), 0, 0, layers},
                          .extent = {std::min(si.extent.width, di.extent.width),
                                     std::min(si.extent.height, di.extent.height),
                                     std::min(si.extent.depth, di.extent.depth)}};
            vkCmdCopyImage(cb, s->image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, d->image.handle(),
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &c);
        } else {
            auto off = [](const VkExtent3D& e) {
                return VkOffset3D{static_cast<int32_t>(e.width), static_cast<int32_t>(e.height),
                                  static_cast<int32_t>(e.depth)};
            };
            VkImageBlit b{.srcSubresource = {s->image.aspect(), 0, 0, layers},
                          .srcOffsets = {{0, 0, 0}, off(si.extent)},
                          .dstSubresource = {d->image.aspect(), 0, 0, layers},
                          .dstOffsets = {{0, 0, 0}, off(di.extent)}};
            vkCmdBlitImage(cb, s->image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, d->image.handle(),
                           VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &b,
                           pd.filter == "nearest" ? VK_FILTER_NEAREST : VK_FILTER_LINEAR);
        }
        return ok_status();
    }

    // 3. Descriptors, written by name for this iteration. The frame block is the pass camera's
    // (a cube camera's face: the layer rendered, else the iteration) with the render area as
    // its resolution (compute: the view size). The same area is the rendering's (step 5):
    // resolve_views (exec/views) refused attachments whose levels differ in size.
    VkExtent2D frame_size{static_cast<uint32_t>(g.view[0]), static_cast<uint32_t>(g.view[1])};
    int frame_layer = iter;
    if (pd.kind != graph::PassKind::compute && (!pd.targets.empty() || pd.depth)) {
        const bool colour = !pd.targets.empty();
        const Sel& sel = colour ? rv.targets[0] : rv.depth;
        frame_size = mip_extent(phys_image(colour ? pd.targets[0].image : pd.depth->target.image, false)->image.info(),
                                static_cast<uint32_t>(std::max(0, sel.mip)));
        if (sel.layer >= 0) frame_layer = sel.layer;
    }
    auto frame_off = frame_offset(pass_camera_[pass_index], frame_layer, frame_size);
    if (!frame_off) {
        Error e = frame_off.error();
        e.pass = pd.name;
        return e;
    }

    std::vector<VkDescriptorSet> sets(pp.set_layouts.size(), VK_NULL_HANDLE);
    for (size_t s = 0; s < sets.size(); ++s) {
        VkDescriptorSetLayout l = pp.set_layouts[s];
        VkDescriptorSetAllocateInfo ai{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO,
                                       .descriptorPool = pool_,
                                       .descriptorSetCount = 1,
                                       .pSetLayouts = &l};
        VK_CHECK(vkAllocateDescriptorSets(ctx_.device(), &ai, &sets[s]));
    }
    std::vector<VkDescriptorImageInfo> image_infos;
    std::vector<VkDescriptorBufferInfo> buffer_infos;
    image_infos.reserve(cp.bindings.size());
    buffer_infos.reserve(cp.bindings.size());
    std::vector<VkWriteDescriptorSet> writes;
    for (size_t k = 0; k < cp.bindings.size(); ++k) {
        const BoundResource& b = cp.bindings[k];
        VkWriteDescriptorSet w{.sType = VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET,
                               .dstSet = sets[b.binding.set],
                               .dstBinding = b.binding.binding,
                               .descriptorCount = 1,
                               .descriptorType = descriptor_type(b.binding.type)};
        switch (b.kind) {
        case BoundResource::Kind::frame:
            buffer_infos.push_back({frame_ubo_.buffer, *frame_off, sizeof(FrameBlock)});
            w.pBufferInfo = &buffer_infos.back();
            break;
        case BoundResource::Kind::cameras:
            buffer_infos.push_back({cameras_ubo_.buffer, 0, VK_WHOLE_SIZE});
            w.pBufferInfo = &buffer_infos.back();
            break;
        case BoundResource::Kind::params:
            buffer_infos.push_back({params_ubo_.buffer, 0, VK_WHOLE_SIZE});
            w.pBufferInfo = &buffer_infos.back();
            break;
        case BoundResource::Kind::buffer:
        case BoundResource::Kind::buffer_prev:
            buffer_infos.push_back({phys_buffer(b.resource, b.kind == BoundResource::Kind::buffer_prev)->buffer.buffer,
                                    0, VK_WHOLE_SIZE});
            w.pBufferInfo = &buffer_infos.back();
            break;
        case BoundResource::Kind::image:
        case BoundResource::Kind::image_prev: {
            GraphImage& gi = image(b.resource);
            PhysImage* p = phys_image(b.resource, b.kind == BoundResource::Kind::image_prev);
            bool storage = b.binding.type == shader::BindingType::storage_image;
            const Sel sel = rv.bindings[k];
            const SubRange range = p->range(sel.mip, sel.layer);
            VkImageView view = storage ? p->storage_view : p->image.view();
            if (sel.mip >= 0 || sel.layer >= 0) {
                // One level (and/or one layer, seen as a 2D image) of the image.
                const auto& info = p->image.info();
                VkImageViewType type = sel.layer >= 0 ? VK_IMAGE_VIEW_TYPE_2D : info.view_type;
                view = p->image.sub_view(type, range.mip, storage ? 1 : range.mips, range.layer, range.layers);
            }
            image_infos.push_back({storage ? VK_NULL_HANDLE : gi.sampler.get(), view, p->state.layout(range)});
            w.pImageInfo = &image_infos.back();
            break;
        }
        }
        if (b.binding.count > 1) {
            return pass_error(pd, "arrays of resources ('" + b.binding.name + "[" +
                                      std::to_string(b.binding.count) + "]') are not supported yet");
        }
        writes.push_back(w);
    }
    if (!writes.empty())
        vkUpdateDescriptorSets(ctx_.device(), static_cast<uint32_t>(writes.size()), writes.data(), 0, nullptr);

    vkCmdBindPipeline(cb, pp.bind_point, pp.pipeline);
    if (!sets.empty())
        vkCmdBindDescriptorSets(cb, pp.bind_point, pp.layout, 0, static_cast<uint32_t>(sets.size()), sets.data(), 0,
                                nullptr);
    // Inside a group a pass without its own repeat sees the group's iteration and count.
    const bool own = !pd.repeat.empty() || !group;
    const int seen_iter = own ? iter : group_iter;
    const int seen_count = own ? cp.repeat : group->repeat;
    if (pp.push_stages) {
        // pl_layer: the layer an expression selects for the first attachment, else the iteration
        // (layer = "iteration" renders layer pl_iteration).
        int layer = seen_iter;
        if (!pd.targets.empty() && !pd.targets[0].layer_expr.empty()) layer = rv.targets[0].layer;
        else if (pd.targets.empty() && pd.depth && !pd.depth->target.layer_expr.empty()) layer = rv.depth.layer;
        PushBlock push{seen_iter, seen_count, layer, group_iter};
        vkCmdPushConstants(cb, pp.layout, pp.push_stages, 0,
                           std::min<uint32_t>(sizeof push, cp.program.reflection.push_constant_size), &push);
    }

    // 4. Compute.
    if (pd.kind == graph::PassKind::compute) {
        if (!pd.indirect.empty()) {
            vkCmdDispatchIndirect(cb, phys_buffer(pd.indirect, false)->buffer.buffer, pd.indirect_offset);
            return ok_status();
        }
        graph::SizeEnv env = size_env(g.desc, g.view);
        bool by_threads = !pd.threads.empty();
        auto v = graph::eval_size(by_threads ? pd.threads : pd.groups, env);
        if (!v) {
            Error e = v.error();
            e.pass = pd.name;
            return e;
        }
        uint32_t n[3] = {1, 1, 1};
        std::vector<int64_t> vals = *v;
        if (vals.size() == 1 && by_threads) vals = {vals[0], 1, 1};
        for (size_t k = 0; k < 3 && k < vals.size(); ++k) {
            int64_t x = vals[k];
            if (by_threads) x = (x + cp.program.reflection.local_size[k] - 1) / cp.program.reflection.local_size[k];
            if (x < 1 || x > 65535)
                return pass_error(pd, "dispatch size " + std::to_string(x) + " in dimension " + std::to_string(k) +
                                          " is outside 1..65535");
            n[k] = static_cast<uint32_t>(x);
        }
        vkCmdDispatch(cb, n[0], n[1], n[2]);
        return ok_status();
    }

    // 5. Raster: dynamic rendering into the pass's targets.
    std::vector<VkRenderingAttachmentInfo> colors;
    VkExtent2D area = frame_size;  // the render area: the first target's level, else the depth's (step 3)
    uint32_t layer_count = 1;
    for (size_t k = 0; k < pd.targets.size(); ++k) {
        const auto& t = pd.targets[k];
        PhysImage* p = phys_image(t.image, false);
        const int layer = rv.targets[k].layer, mip = rv.targets[k].mip;
        if (layer >= 0 && static_cast<uint32_t>(layer) >= std::max(p->image.info().layers, p->image.info().extent.depth))
            return pass_error(pd, "target '" + t.image + "' has no layer " + std::to_string(layer));
        VkRenderingAttachmentInfo a{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO,
                                    .imageView = p->image.attachment_view(static_cast<uint32_t>(mip), layer),
                                    .imageLayout = p->state.layout(p->range(mip, layer)),
                                    .loadOp = pd.clear.color ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD,
                                    .storeOp = VK_ATTACHMENT_STORE_OP_STORE};
        if (pd.clear.color) a.clearValue.color = vk::clear_color(*image(t.image).format, *pd.clear.color);
        if (!t.resolve.empty()) {
            PhysImage* r = phys_image(t.resolve, false);
            a.resolveMode = image(t.image).format->is_integer ? VK_RESOLVE_MODE_SAMPLE_ZERO_BIT : VK_RESOLVE_MODE_AVERAGE_BIT;
            a.resolveImageView = r->image.attachment_view(0, layer);
            a.resolveImageLayout = r->state.layout(r->range(0, layer));
        }
        colors.push_back(a);
        if (k == 0 && layer == -1) layer_count = p->image.info().layers;
    }
    VkRenderingAttachmentInfo depth{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    VkRenderingAttachmentInfo stencil{.sType = VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
    bool has_stencil = false;
    if (pd.depth) {
        PhysImage* p = phys_image(pd.depth->target.image, false);
        const int layer = rv.depth.layer, mip = rv.depth.mip;
        depth.imageView = p->image.attachment_view(static_cast<uint32_t>(mip), layer);
        depth.imageLayout = p->state.layout(p->range(mip, layer));
        depth.loadOp = pd.clear.depth ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
        depth.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
        depth.clearValue.depthStencil = {pd.clear.depth.value_or(1.0f), pd.clear.stencil.value_or(0)};
        has_stencil = image(pd.depth->target.image).format->has_stencil;
        if (has_stencil) {
            stencil = depth;
            stencil.loadOp = pd.clear.stencil ? VK_ATTACHMENT_LOAD_OP_CLEAR : VK_ATTACHMENT_LOAD_OP_LOAD;
        }
        if (colors.empty() && layer == -1) layer_count = p->image.info().layers;
    }
    if (colors.empty() && !pd.depth) return pass_error(pd, "the pass has no targets and no depth attachment to render into");
    VkRenderingInfo ri{.sType = VK_STRUCTURE_TYPE_RENDERING_INFO,
                       .renderArea = {{0, 0}, area},
                       .layerCount = layer_count,
                       .colorAttachmentCount = static_cast<uint32_t>(colors.size()),
                       .pColorAttachments = colors.data(),
                       .pDepthAttachment = pd.depth ? &depth : nullptr,
                       .pStencilAttachment = has_stencil ? &stencil : nullptr};
    vkCmdBeginRendering(cb, &ri);
    VkViewport vp{0.0f, 0.0f, static_cast<float>(area.width), static_cast<float>(area.height), 0.0f, 1.0f};
    VkRect2D sc{{0, 0}, area};
    vkCmdSetViewport(cb, 0, 1, &vp);
    vkCmdSetScissor(cb, 0, 1, &sc);
    if (pd.kind == graph::PassKind::fullscreen) {
        vkCmdDraw(cb, 3, 1, 0, 0);
    } else {
        const GpuMesh* mesh = pd.mesh.empty() ? nullptr : &res_.meshes.at(pd.mesh);
        uint32_t instances = pd.instances ? static_cast<uint32_t>(*pd.instances) : mesh ? mesh->instances : 1u;
        // With adjacency the mesh is drawn from its 6-indices-per-triangle list.
        const bool adjacency = mesh && pd.topology == "triangles_adjacency";
        const uint32_t index_count = mesh ? (adjacency ? mesh->adjacency_count : mesh->index_count) : 0;
        if (mesh) {
            VkDeviceSize zero = 0;
            VkBuffer vb[2] = {mesh->vertices.buffer, mesh->morph.buffer};  // binding 1: geomorph targets
            VkDeviceSize offsets[2] = {zero, zero};
            vkCmdBindVertexBuffers(cb, 0, mesh->has_morph ? 2u : 1u, vb, offsets);
            vkCmdBindIndexBuffer(cb, adjacency ? mesh->adjacency.buffer : mesh->indices.buffer, 0, VK_INDEX_TYPE_UINT32);
        }
        if (!pd.indirect.empty()) {
            VkBuffer ib = phys_buffer(pd.indirect, false)->buffer.buffer;
            if (mesh) vkCmdDrawIndexedIndirect(cb, ib, pd.indirect_offset, 1, sizeof(VkDrawIndexedIndirectCommand));
            else vkCmdDrawIndirect(cb, ib, pd.indirect_offset, 1, sizeof(VkDrawIndirectCommand));
        } else if (instance_order_ != InstanceOrder::natural && instances > 1) {
            // One call per instance, in permuted order; firstInstance keeps gl_InstanceIndex.
            std::vector<uint32_t> order(instances);
            for (uint32_t i = 0; i < instances; ++i) order[i] = instances - 1 - i;
            if (instance_order_ == InstanceOrder::shuffled) {
                uint32_t state = 0x9e3779b9u;  // fixed seed: the shuffle is the same every run
                for (uint32_t i = instances - 1; i > 0; --i) {
                    state = state * 1664525u + 1013904223u;
                    std::swap(order[i], order[state % (i + 1)]);
                }
            }
            for (uint32_t i : order) {
                if (mesh) vkCmdDrawIndexed(cb, index_count, 1, 0, 0, i);
                else vkCmdDraw(cb, static_cast<uint32_t>(std::max(0, pd.vertex_count)), 1, 0, i);
            }
        } else if (mesh) {
            vkCmdDrawIndexed(cb, index_count, instances, 0, 0, 0);
        } else {
            vkCmdDraw(cb, static_cast<uint32_t>(std::max(0, pd.vertex_count)), instances, 0, 0);
        }
    }
    vkCmdEndRendering(cb);
    return ok_status();
}

Status Executor::check_showable(const std::string& name) const {
    auto it = res_.images.find(name);
    if (it == res_.images.end()) return make_error("no image named '" + name + "' to show");
    const PhysImage* p = it->second.phys[0].get();
    const auto& info = p->image.info();
    const vk::FormatInfo* f = it->second.format;
    // A blit converts only between float/unorm formats, never from integer or compressed ones;
    // such an output needs a display pass (or the image viewer, which converts any format).
    VkFormatProperties fp;
    vkGetPhysicalDeviceFormatProperties(ctx_.physical(), info.format, &fp);
    std::string why;
    if (info.samples != VK_SAMPLE_COUNT_1_BIT) why = "is multisampled";
    else if (p->image.aspect() & VK_IMAGE_ASPECT_DEPTH_BIT) why = "is a depth image";
    else if (f->is_integer || f->compressed() || !(fp.optimalTilingFeatures & VK_FORMAT_FEATURE_BLIT_SRC_BIT))
        why = std::string("has format ") + f->name + ", which cannot be blitted";
    if (why.empty()) return ok_status();
    Error e = make_error("output image '" + name + "' " + why + ": the window cannot show it directly");
    if (it->second.desc) e.loc = it->second.desc->loc;
    e.resource = name;
    e.hint = "add a fullscreen pass that converts it to rgba8 or rgba16f and name that in [output], or "
             "inspect it in the panel's image viewer";
    return e;
}

Status Executor::record_blit_to(VkCommandBuffer cb, const std::string& name, VkImage dst, VkRect2D to) {
    if (auto s = check_showable(name); !s) return s;
    auto it = res_.images.find(name);
    PhysImage* p = it->second.phys[last_parity()].get();
    const auto& info = p->image.info();
    // Formats that cannot be filtered linearly (32-bit float on some GPUs) are shown nearest.
    VkFormatProperties fp;
    vkGetPhysicalDeviceFormatProperties(ctx_.physical(), info.format, &fp);
    VkFilter filter = fp.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT ? VK_FILTER_LINEAR
                                                                                                 : VK_FILTER_NEAREST;
    BarrierBatch batch;
    require(batch, *p, p->range(0, 0), usage_of(Access::transfer_src, 0));
    batch.flush(cb);
    VkImageBlit b{.srcSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                  .srcOffsets = {{0, 0, 0}, {static_cast<int32_t>(info.extent.width), static_cast<int32_t>(info.extent.height), 1}},
                  .dstSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, 1},
                  .dstOffsets = {{to.offset.x, to.offset.y, 0},
                                 {to.offset.x + static_cast<int32_t>(to.extent.width), to.offset.y + static_cast<int32_t>(to.extent.height), 1}}};
    vkCmdBlitImage(cb, p->image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, dst, VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &b,
                   filter);
    return ok_status();
}

Result<image::Image> Executor::read(const std::string& name, int mip, int layer) {
    auto it = res_.images.find(name);
    if (it == res_.images.end()) return no_resource("image", name, res_.images);
    GraphImage& gi = it->second;
    PhysImage* p = gi.phys[last_parity()].get();
    const auto& info = p->image.info();
    if (info.samples != VK_SAMPLE_COUNT_1_BIT) {
        Error e = make_error("image '" + name + "' is multisampled and cannot be read back; read its resolve target");
        e.resource = name;
        return e;
    }
    bool is3d = info.type == VK_IMAGE_TYPE_3D;
    uint32_t nlayers = is3d ? std::max(1u, info.extent.depth >> mip) : info.layers;
    if (mip < 0 || static_cast<uint32_t>(mip) >= info.mips || layer < 0 || static_cast<uint32_t>(layer) >= nlayers) {
        Error e = make_error("image '" + name + "' has " + std::to_string(info.mips) + " mip(s) and " +
                             std::to_string(nlayers) + " layer(s); mip " + std::to_string(mip) + " layer " +
                             std::to_string(layer) + " does not exist");
        e.resource = name;
        return e;
    }
    if (gi.format->compressed()) {
        Error e = make_error("image '" + name + "' is block-compressed (" + gi.format->name +
                             ") and cannot be read back; sample it into a colour image and read that");
        e.resource = name;
        return e;
    }
    VkExtent2D ext = mip_extent(info, static_cast<uint32_t>(mip));
    uint32_t texel = copy_texel_size(*gi.format);
    VkDeviceSize bytes = static_cast<VkDeviceSize>(ext.width) * ext.height * texel;
    vk::Buffer staging = vk::create_buffer(ctx_, bytes, VK_BUFFER_USAGE_TRANSFER_DST_BIT, true);
    bool depth = gi.format->is_depth;
    Status st = ctx_.run_once(
        [&](VkCommandBuffer cb) {
            BarrierBatch batch;
            require(batch, *p, p->range(mip, layer), usage_of(Access::transfer_src, 0));
            batch.flush(cb);
            VkBufferImageCopy c{
                .imageSubresource = {depth ? static_cast<VkImageAspectFlags>(VK_IMAGE_ASPECT_DEPTH_BIT)
                                           : static_cast<VkImageAspectFlags>(VK_IMAGE_ASPECT_COLOR_BIT),
                                     static_cast<uint32_t>(mip), is3d ? 0u : static_cast<uint32_t>(layer), 1},
                .imageOffset = {0, 0, is3d ? layer : 0},
                .imageExtent = {ext.width, ext.height, 1}};
            vkCmdCopyImageToBuffer(cb, p->image.handle(), VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, staging.buffer, 1, &c);
            transfer_to_host(cb);  // the host reads the staging buffer below
        },
        timeout_);
    if (!st) return st.error();
    image::Image out;
    out.width = static_cast<int>(ext.width);
    out.height = static_cast<int>(ext.height);
    out.pixels.resize(static_cast<size_t>(ext.width) * ext.height * 4);
    const auto* src = static_cast<const uint8_t*>(staging.mapped);
    for (size_t i = 0; i < static_cast<size_t>(ext.width) * ext.height; ++i)
        if (!decode_texel(*gi.format, src + i * texel, &out.pixels[i * 4], depth)) {
            Error e = make_error("image '" + name + "' has format " + gi.format->name + ", which cannot be read back");
            e.resource = name;
            return e;
        }
    return out;
}

} // namespace pl::exec
