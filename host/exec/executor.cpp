#include "exec/executor.hpp"

#include "exec/barriers.hpp"
#include "exec/bind.hpp"
#include "exec/frame_block.hpp"
#include "exec/limits.hpp"
#include "exec/texels.hpp"
#include "scene/camera.hpp"
#include "vk/check.hpp"
#include "vk/clear_value.hpp"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstring>
#include <map>

namespace pl::exec {

namespace {




scene::OrbitCamera to_camera(const graph::ViewDesc& v, const graph::OrbitCamera& o) {
    scene::OrbitCamera c;
    c.target = {o.target[0], o.target[1], o.target[2]};
    c.distance = o.distance;
    c.yaw_deg = o.yaw;
    c.pitch_deg = o.pitch;
    c.fov_deg = v.fov;
    c.near = v.near;
    c.far = v.far;
    c.ortho = v.ortho;
    c.ortho_height = v.ortho_height;
    return c;
}

} // namespace

Executor::~Executor() {
    if (ctx_.hung()) {
        // Objects the running shader uses must outlive it: give them up instead of destroying.
        // That is every GPU object of this executor, the command buffer's pools, the fence it
        // signals and the query pool it writes included (destroying those was a validation error
        // and once a crash); the process ends soon after (see ContextSlot).
        new GraphResources(std::move(res_));
        new std::vector<std::shared_ptr<PassPipeline>>(std::move(pipelines_));
        new vk::Buffer[4]{std::move(frame_ubo_), std::move(params_ubo_), std::move(cameras_ubo_),
                          std::move(counter_readback_)};
        (void)pool_.release();
        (void)cmd_pool_.release();
        (void)fence_.release();
        (void)queries_.release();
        return;
    }
    if (ctx_.device()) vkDeviceWaitIdle(ctx_.device());
}

std::string Executor::timeout_cause() const {
    // A runaway loop is the usual cause, but a frame can also be slow only because it is big:
    // say which when the graph is large enough for that to be plausible.
    std::string big;
    double largest = 0;
    for (const auto& [name, gi] : res_.images) {
        double texels = double(gi.extent.width) * gi.extent.height * gi.extent.depth * gi.layers;
        if (texels > largest && texels > 4096.0 * 4096.0) {
            largest = texels;
            big = "image '" + name + "' is " + std::to_string(gi.extent.width) + "x" + std::to_string(gi.extent.height);
        }
    }
    for (const auto& [name, m] : res_.meshes)
        if (double(m.index_count) / 3 * m.instances > 2e7)
            big = "mesh '" + name + "' draws " + std::to_string(uint64_t(m.index_count) / 3 * m.instances) + " triangles";
    if (big.empty()) return "a shader probably runs away (endless or very long loop)";
    return "the frame is large (" + big + "), so it may be slow rather than endless";
}

Result<std::unique_ptr<Executor>> Executor::create(vk::Context& ctx, CompiledGraph graph, PipelineCache* cache) {
    std::unique_ptr<Executor> ex(new Executor(ctx));
    ex->graph_ = std::make_unique<CompiledGraph>(std::move(graph));
    CompiledGraph& g = *ex->graph_;
    VkDevice dev = ctx.device();

    if (auto s = check_compute_limits(ctx.properties().limits, ctx.properties().deviceName, g); !s) return s.error();
    auto res = create_resources(ctx, g);
    if (!res) return res.error();
    ex->res_ = std::move(res.value());
    std::map<std::string, VkDeviceSize> buffer_sizes;
    for (const auto& [name, gb] : ex->res_.buffers) buffer_sizes[name] = gb.phys[0]->buffer.size;
    if (auto s = check_binding_limits(ctx.properties().limits, ctx.properties().deviceName, g, buffer_sizes); !s) return s.error();
    if (auto s = ex->create_counters(); !s) return s.error();

    std::map<VkDescriptorType, uint32_t> counts;
    uint32_t max_sets = 0;
    for (const auto& cp : g.passes) {
        ctx.set_label("pass '" + cp.desc->name + "' (pipeline)");
        bool reused = false;
        auto pp = create_pass_pipeline(ctx, g, cp, ex->res_, cache, &reused);
        if (!pp) return pp.error();
        if (!reused && (*pp)->pipeline) ex->rebuilt_.push_back(cp.desc->name);
        // One set per run: its own repeat times its group's.
        const uint32_t runs = static_cast<uint32_t>(cp.runs.size());
        for (const auto& b : cp.program.reflection.bindings) counts[descriptor_type(b.type)] += b.count * runs;
        max_sets += static_cast<uint32_t>((*pp)->set_layouts.size()) * runs;
        ex->pipelines_.push_back(std::move(pp.value()));
    }
    ctx.set_label("");

    // Frame blocks: one slot per distinct (camera, face, render size) a frame uses. A pass sees
    // at most 6 faces x 16 mip sizes, and at most one per run (group iteration x repeat).
    const VkDeviceSize align = std::max<VkDeviceSize>(1, ctx.properties().limits.minUniformBufferOffsetAlignment);
    ex->frame_stride_ = (sizeof(FrameBlock) + align - 1) / align * align;
    ex->frame_capacity_ = 1;
    for (const auto& cp : g.passes) {
        if (!cp.program.reflection.bindings.empty())
            ex->frame_capacity_ += static_cast<uint32_t>(std::min<size_t>(std::max<size_t>(cp.runs.size(), static_cast<size_t>(cp.repeat)), 6 * 16));
        const graph::CameraDesc* cam = cp.desc->camera.empty() ? nullptr : g.desc.find_camera(cp.desc->camera);
        ex->pass_camera_.push_back(cam ? static_cast<int>(cam - g.desc.cameras.data()) : -1);
    }
    ex->frame_ubo_ = vk::create_buffer(ctx, ex->frame_stride_ * ex->frame_capacity_, VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
    int camera_entries = 0;
    for (const auto& c : g.desc.cameras) camera_entries += c.faces();
    ex->cameras_ubo_ = vk::create_buffer(ctx, std::max<VkDeviceSize>(16, camera_entries * sizeof(CameraBlock)),
                                         VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);
    ex->params_ubo_ = vk::create_buffer(ctx, std::max<uint32_t>(16, g.param_layout.size),
                                        VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT, true);

    std::vector<VkDescriptorPoolSize> sizes;
    for (auto [type, n] : counts) sizes.push_back({type, n});
    if (sizes.empty()) sizes.push_back({VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1});
    VkDescriptorPoolCreateInfo dpci{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO,
                                    .maxSets = std::max(1u, max_sets),
                                    .poolSizeCount = static_cast<uint32_t>(sizes.size()),
                                    .pPoolSizes = sizes.data()};
    VkDescriptorPool pool;
    VK_CHECK(vkCreateDescriptorPool(dev, &dpci, nullptr, &pool));
    ex->pool_ = vk::UniqueDescriptorPool(dev, pool);

    VkCommandPoolCreateInfo cpci{.sType = VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO,
                                 .flags = VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT,
                                 .queueFamilyIndex = ctx.queue_family()};
    VkCommandPool cmd_pool;
    VK_CHECK(vkCreateCommandPool(dev, &cpci, nullptr, &cmd_pool));
    ex->cmd_pool_ = vk::UniqueCommandPool(dev, cmd_pool);
    VkCommandBufferAllocateInfo cai{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO,
                                    .commandPool = cmd_pool,
                                    .level = VK_COMMAND_BUFFER_LEVEL_PRIMARY,
                                    .commandBufferCount = 1};
    VK_CHECK(vkAllocateCommandBuffers(dev, &cai, &ex->cmd_));
    VkFenceCreateInfo fci{.sType = VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    VK_CHECK(vkCreateFence(dev, &fci, nullptr, &fence));
    ex->fence_ = vk::UniqueFence(dev, fence);

    uint32_t qf_count = 0;
    vkGetPhysicalDeviceQueueFamilyProperties(ctx.physical(), &qf_count, nullptr);
    std::vector<VkQueueFamilyProperties> qfs(qf_count);
    vkGetPhysicalDeviceQueueFamilyProperties(ctx.physical(), &qf_count, qfs.data());
    if (qfs[ctx.queue_family()].timestampValidBits > 0 && !g.passes.empty()) {
        VkQueryPoolCreateInfo qci{.sType = VK_STRUCTURE_TYPE_QUERY_POOL_CREATE_INFO,
                                  .queryType = VK_QUERY_TYPE_TIMESTAMP,
                                  .queryCount = static_cast<uint32_t>(2 * g.passes.size())};
        VkQueryPool qp;
        VK_CHECK(vkCreateQueryPool(dev, &qci, nullptr, &qp));
        ex->queries_ = vk::UniqueQueryPool(dev, qp);
        ex->timestamps_ = true;
    }
    return ex;
}

Status Executor::render(const FrameInput& in) {
    CompiledGraph& g = *graph_;
    const auto t_record = std::chrono::steady_clock::now();
    frame_parity_ = frames_rendered_ & 1;
    instance_order_ = in.instance_order;

    // Named cameras follow the current params (the panel may have moved them).
    auto params = pack_params(g.desc.params, g.param_layout);
    if (!g.desc.cameras.empty()) {
        // A param the panel moved to a value a camera cannot take (eye on its target, near = 0)
        // keeps the last good cameras and says why, rather than ending the live lab; the build
        // checked the starting values, so a first frame cannot get here.
        auto cams = eval_cameras(g.desc.cameras, size_env(g.desc, g.view));
        if (!cams && cameras_.entries.empty()) return cams.error();
        camera_error_ = cams ? std::string() : cams.error().message;
        if (cams) cameras_ = std::move(cams.value());
        std::memcpy(cameras_ubo_.mapped, cameras_.entries.data(), cameras_.entries.size() * sizeof(CameraBlock));
        if (prev_camera_view_proj_.size() != cameras_.entries.size()) {  // first frame: no motion
            prev_camera_view_proj_.clear();
            for (const auto& c : cameras_.entries) prev_camera_view_proj_.push_back(c.view_proj);
        }
    }

    // Frame block of the view; passes with another camera or render size get their own copies.
    FrameBlock fb{};
    const float w = static_cast<float>(g.view[0]), h = static_cast<float>(g.view[1]);
    const graph::OrbitCamera orbit = in.camera ? *in.camera : g.desc.view.orbit;
    scene::OrbitCamera cam = to_camera(g.desc.view, orbit);
    fb.view = cam.view();
    fb.proj = cam.projection(w / h);
    // Jitter in pixels -> clip-space offset (2 px = full NDC width / w ... per unit of w).
    fb.proj[2][0] += in.jitter.x * 2.0f / w;
    fb.proj[2][1] += in.jitter.y * 2.0f / h;
    fb.view_proj = fb.proj * fb.view;
    fb.inv_view = glm::inverse(fb.view);
    fb.inv_proj = glm::inverse(fb.proj);
    fb.inv_view_proj = glm::inverse(fb.view_proj);
    fb.prev_view_proj = frames_rendered_ == 0 ? fb.view_proj : prev_view_proj_;
    fb.camera_pos = glm::vec4(cam.position(), 1.0f);
    fb.resolution = {w, h, 1.0f / w, 1.0f / h};
    fb.mouse = in.mouse;
    std::memcpy(fb.keys, in.keys.bits.data(), sizeof fb.keys);
    fb.jitter = {in.jitter.x, in.jitter.y, 0.0f, 0.0f};
    fb.time = static_cast<float>(in.time);
    fb.delta = static_cast<float>(in.delta);
    fb.index = in.index;
    fb.aspect = w / h;
    fb.target = fb.resolution;

    // Accumulation: the count restarts whenever what the picture depends on changes.
    std::vector<uint8_t> key = params;
    auto append = [&](const void* p, size_t n) { key.insert(key.end(), static_cast<const uint8_t*>(p), static_cast<const uint8_t*>(p) + n); };
    append(&orbit, sizeof orbit);
    append(g.view.data(), sizeof g.view);
    append(cameras_.entries.data(), cameras_.entries.size() * sizeof(CameraBlock));
    accum_frame_ = !accum_key_.empty() && key == accum_key_ ? accum_frame_ + 1 : 0;
    accum_key_ = std::move(key);
    fb.accum_frame = accum_frame_;

    frame_base_ = fb;
    frame_slots_.assign(1, FrameSlot{-1, static_cast<uint32_t>(g.view[0]), static_cast<uint32_t>(g.view[1])});
    std::memcpy(frame_ubo_.mapped, &fb, sizeof fb);
    prev_view_proj_ = fb.view_proj;
    std::memcpy(params_ubo_.mapped, params.data(), std::min<size_t>(params.size(), params_ubo_.size));
    run_baked_ = !baked_ || params != baked_params_;
    baked_ = true;
    baked_params_ = std::move(params);

    VK_CHECK(vkResetDescriptorPool(ctx_.device(), pool_, 0));
    VK_CHECK(vkResetCommandBuffer(cmd_, 0));
    VkCommandBufferBeginInfo bi{.sType = VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO,
                                .flags = VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
    VK_CHECK(vkBeginCommandBuffer(cmd_, &bi));
    Status st = record_frame(cmd_, in);
    VK_CHECK(vkEndCommandBuffer(cmd_));
    for (size_t e = 0; e < cameras_.entries.size(); ++e) prev_camera_view_proj_[e] = cameras_.entries[e].view_proj;
    record_ms_ = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t_record).count();
    ctx_.set_label("");
    if (!st) return st;

    VkSubmitInfo si{.sType = VK_STRUCTURE_TYPE_SUBMIT_INFO, .commandBufferCount = 1, .pCommandBuffers = &cmd_};
    uint64_t serial = ctx_.begin_submit();
    VK_CHECK(vkQueueSubmit(ctx_.queue(), 1, &si, fence_));
    if (auto w = ctx_.wait(fence_, timeout_, "frame " + std::to_string(in.index), timeout_cause()); !w) {
        (void)fence_.release();  // the GPU may still run the shader: never destroy what it uses
        Error e = w.error();
        std::error_code ec;
        e.loc = {std::filesystem::proximate(g.desc.file, ec).string(), 0, 0};
        std::string passes;
        for (size_t i : g.order) {
            const auto& pd = *g.passes[i].desc;
            std::string shader = !pd.fragment.empty() ? pd.fragment.file : pd.compute.file;
            passes += (passes.empty() ? "" : ", ") + pd.name + (shader.empty() ? "" : " (" + shader + ")");
        }
        e.notes.push_back("passes in the frame: " + passes);
        return e;
    }
    VkFence f = fence_;
    VK_CHECK(vkResetFences(ctx_.device(), 1, &f));
    ctx_.collect(serial);
    ++frames_rendered_;
    collect_counters();

    timings_.clear();
    if (timestamps_) {
        std::vector<uint64_t> ts(2 * g.passes.size(), 0);
        VkResult r = vkGetQueryPoolResults(ctx_.device(), queries_, 0, static_cast<uint32_t>(ts.size()),
                                           ts.size() * sizeof(uint64_t), ts.data(), sizeof(uint64_t),
                                           VK_QUERY_RESULT_64_BIT);
        double period_ms = ctx_.properties().limits.timestampPeriod * 1e-6;
        for (size_t i : g.order) {
            double ms = r == VK_SUCCESS ? static_cast<double>(ts[2 * i + 1] - ts[2 * i]) * period_ms : 0.0;
            const CompiledPass& cp = g.passes[i];
            if (cp.group < 0) {
                timings_.push_back({cp.desc->name, ms});
                continue;
            }
            // A group is timed as a whole (its members interleave every iteration): one row
            // named after the group and its members, instead of a time on the first member and
            // zeros on the others.
            const CompiledGroup& gr = g.groups[static_cast<size_t>(cp.group)];
            if (i != gr.members.front()) continue;
            std::string name = "group " + gr.desc->name + " (";
            for (size_t k = 0; k < gr.members.size(); ++k) name += (k ? ", " : "") + g.passes[gr.members[k]].desc->name;
            timings_.push_back({name + ") x" + std::to_string(gr.repeat), ms});
        }
    }
    return ok_status();
}

Result<VkDeviceSize> Executor::frame_offset(int camera, int layer, VkExtent2D size) {
    int entry = -1;
    if (camera >= 0) {
        const graph::CameraDesc& c = graph_->desc.cameras[static_cast<size_t>(camera)];
        entry = cameras_.first[static_cast<size_t>(camera)] + (c.cube ? std::max(0, layer) % 6 : 0);
    }
    for (size_t k = 0; k < frame_slots_.size(); ++k)
        if (frame_slots_[k].entry == entry && frame_slots_[k].w == size.width && frame_slots_[k].h == size.height)
            return static_cast<VkDeviceSize>(k) * frame_stride_;
    if (frame_slots_.size() >= frame_capacity_)  // cannot happen: the capacity bounds the distinct pairs
        return make_error("internal: more frame blocks than the " + std::to_string(frame_capacity_) + " allocated");
    FrameBlock fb = frame_base_;
    if (entry >= 0) apply_camera(fb, cameras_.entries[static_cast<size_t>(entry)], prev_camera_view_proj_[static_cast<size_t>(entry)]);
    const float w = static_cast<float>(size.width), h = static_cast<float>(size.height);
    fb.target = {w, h, 1.0f / w, 1.0f / h};
    // `resolution` stays the view's for passes without a camera: presets rely on it (a 1x1
    // analysis pass measuring the view); a camera pass is new and sees its own render area.
    if (entry >= 0) fb.resolution = fb.target;
    const VkDeviceSize off = frame_slots_.size() * frame_stride_;
    std::memcpy(static_cast<uint8_t*>(frame_ubo_.mapped) + off, &fb, sizeof fb);
    frame_slots_.push_back({entry, size.width, size.height});
    return off;
}

Status Executor::record_frame(VkCommandBuffer cb, const FrameInput&) {
    CompiledGraph& g = *graph_;
    if (timestamps_) vkCmdResetQueryPool(cb, queries_, 0, static_cast<uint32_t>(2 * g.passes.size()));
    ctx_.set_label("frame start");

    // Per-frame clears and first-frame history initialisation, derived like any other write.
    BarrierBatch batch;
    struct ClearOp {
        PhysImage* img;
        const vk::FormatInfo* format;
        std::array<double, 4> color;
    };
    std::vector<ClearOp> clears;
    for (auto& [name, gi] : res_.images) {
        if (!gi.desc->alias.empty()) continue;
        std::array<double, 4> value = gi.desc->clear.value_or(std::array<double, 4>{0, 0, 0, 0});
        if (gi.desc->clear) clears.push_back({gi.phys[static_cast<size_t>(frame_parity_)].get(), gi.format, value});
        if (gi.history && frames_rendered_ == 0)
            clears.push_back({gi.phys[static_cast<size_t>(1 - frame_parity_)].get(), gi.format, value});
    }
    for (auto& c : clears) require(batch, *c.img, usage_of(Access::transfer_dst, 0), true);
    std::vector<PhysBuffer*> fills;
    for (auto& [name, gb] : res_.buffers)
        if (gb.desc->clear) {
            PhysBuffer* pb = gb.phys[static_cast<size_t>(frame_parity_)].get();
            require(batch, *pb, usage_of(Access::transfer_dst, 0));
            fills.push_back(pb);
        }
    batch.flush(cb);
    for (auto& c : clears) {
        auto range = c.img->image.full_range();
        if (c.img->image.aspect() & VK_IMAGE_ASPECT_DEPTH_BIT) {
            VkClearDepthStencilValue v{static_cast<float>(c.color[0]), 0};
            vkCmdClearDepthStencilImage(cb, c.img->image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &v, 1, &range);
        } else {
            VkClearColorValue v = vk::clear_color(*c.format, c.color);
            vkCmdClearColorImage(cb, c.img->image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, &v, 1, &range);
        }
    }
    for (auto& [name, gb] : res_.buffers)
        if (gb.desc->clear)
            vkCmdFillBuffer(cb, gb.phys[static_cast<size_t>(frame_parity_)]->buffer.buffer, 0, VK_WHOLE_SIZE,
                            *gb.desc->clear);

    // Passes with `enabled = "expr"` follow the current param values (the panel changes them);
    // the environment is built only in frames that have such a pass.
    std::optional<graph::SizeEnv> env;
    auto runs_now = [&](const CompiledPass& cp) {
        bool on = cp.desc->enabled;
        if (on && !cp.desc->enabled_when.empty()) {
            if (!env) env = size_env(g.desc, g.view);
            auto v = graph::eval_scalar(cp.desc->enabled_when, *env);
            on = v && *v != 0;  // evaluated at build time too, so an error here cannot happen
        }
        return on && !(cp.desc->bake && !run_baked_);  // baked: its images still hold the result
    };
    auto stamp = [&](VkPipelineStageFlags2 stage, size_t query) {
        if (timestamps_) vkCmdWriteTimestamp2(cb, stage, queries_, static_cast<uint32_t>(query));
    };
    for (size_t i : g.order) {
        const CompiledPass& cp = g.passes[i];
        if (cp.group >= 0) {
            // A group runs from its first member: every member in listed order, `repeat` times,
            // timed as a whole (the others' queries are written only to stay valid).
            const CompiledGroup& gr = g.groups[static_cast<size_t>(cp.group)];
            if (i != gr.members.front()) continue;
            ctx_.set_label("group '" + gr.desc->name + "'");
            stamp(VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, 2 * i);
            std::vector<char> on;
            for (size_t m : gr.members) on.push_back(runs_now(g.passes[m]));
            for (int gi = 0; gi < gr.repeat; ++gi)
                for (size_t k = 0; k < gr.members.size(); ++k) {
                    if (!on[k]) continue;
                    const size_t m = gr.members[k];
                    ctx_.set_label("pass '" + g.passes[m].desc->name + "' (group '" + gr.desc->name + "' iteration " +
                                   std::to_string(gi) + ")");
                    for (int it = 0; it < g.passes[m].repeat; ++it)
                        if (auto s = record_pass(cb, m, it, gi); !s) return s;
                }
            stamp(VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, 2 * i + 1);
            for (size_t m : gr.members)
                if (m != i) {
                    stamp(VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, 2 * m);
                    stamp(VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, 2 * m + 1);
                }
            continue;
        }
        ctx_.set_label("pass '" + cp.desc->name + "'");
        stamp(VK_PIPELINE_STAGE_2_TOP_OF_PIPE_BIT, 2 * i);
        const bool on = runs_now(cp);
        for (int it = 0; on && it < cp.repeat; ++it)
            if (auto s = record_pass(cb, i, it); !s) return s;
        stamp(VK_PIPELINE_STAGE_2_BOTTOM_OF_PIPE_BIT, 2 * i + 1);
    }
    record_counter_reads(cb);
    return ok_status();
}

} // namespace pl::exec
