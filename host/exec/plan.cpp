#include "exec/plan.hpp"

#include <algorithm>
#include <functional>
#include <map>
#include <queue>
#include <set>

namespace pl::exec {

namespace {
constexpr VkAccessFlags2 kWriteAccessMask =
    VK_ACCESS_2_SHADER_WRITE_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT |
    VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT |
    VK_ACCESS_2_TRANSFER_WRITE_BIT | VK_ACCESS_2_HOST_WRITE_BIT | VK_ACCESS_2_MEMORY_WRITE_BIT;
}

Usage usage_of(Access a, VkPipelineStageFlags2 shader_stages) {
    switch (a) {
    case Access::sampled:
        return {VK_IMAGE_LAYOUT_SHADER_READ_ONLY_OPTIMAL, shader_stages, VK_ACCESS_2_SHADER_SAMPLED_READ_BIT, false};
    case Access::storage_read:
        return {VK_IMAGE_LAYOUT_GENERAL, shader_stages, VK_ACCESS_2_SHADER_STORAGE_READ_BIT, false};
    case Access::storage_write:
        return {VK_IMAGE_LAYOUT_GENERAL, shader_stages, VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, true};
    case Access::storage_read_write:
        return {VK_IMAGE_LAYOUT_GENERAL, shader_stages,
                VK_ACCESS_2_SHADER_STORAGE_READ_BIT | VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT, true};
    case Access::uniform_read:
        return {VK_IMAGE_LAYOUT_UNDEFINED, shader_stages, VK_ACCESS_2_UNIFORM_READ_BIT, false};
    case Access::color_attachment:
        // Read access too: blending and load-op LOAD read the attachment.
        return {VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_READ_BIT | VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, true};
    case Access::resolve_dst:
        return {VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL, VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT,
                VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT, true};
    case Access::depth_attachment:
        return {VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL,
                VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT | VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_WRITE_BIT,
                true};
    case Access::depth_read:
        return {VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL,
                VK_PIPELINE_STAGE_2_EARLY_FRAGMENT_TESTS_BIT | VK_PIPELINE_STAGE_2_LATE_FRAGMENT_TESTS_BIT,
                VK_ACCESS_2_DEPTH_STENCIL_ATTACHMENT_READ_BIT, false};
    case Access::transfer_src:
        return {VK_IMAGE_LAYOUT_TRANSFER_SRC_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                VK_ACCESS_2_TRANSFER_READ_BIT, false};
    case Access::transfer_dst:
        return {VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT,
                VK_ACCESS_2_TRANSFER_WRITE_BIT, true};
    case Access::indirect_read:
        return {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_DRAW_INDIRECT_BIT,
                VK_ACCESS_2_INDIRECT_COMMAND_READ_BIT, false};
    case Access::vertex_read:
        return {VK_IMAGE_LAYOUT_UNDEFINED, VK_PIPELINE_STAGE_2_VERTEX_INPUT_BIT,
                VK_ACCESS_2_VERTEX_ATTRIBUTE_READ_BIT | VK_ACCESS_2_INDEX_READ_BIT, false};
    }
    return {};
}

Usage merge(const Usage& a, const Usage& b) {
    Usage u;
    u.layout = a.layout == b.layout ? a.layout : VK_IMAGE_LAYOUT_GENERAL;
    // Depth tested read-only in one use and written in another: the writable layout covers both.
    if (a.layout != b.layout &&
        ((a.layout == VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL &&
          b.layout == VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL) ||
         (b.layout == VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL &&
          a.layout == VK_IMAGE_LAYOUT_DEPTH_STENCIL_READ_ONLY_OPTIMAL)))
        u.layout = VK_IMAGE_LAYOUT_DEPTH_STENCIL_ATTACHMENT_OPTIMAL;
    u.stages = a.stages | b.stages;
    u.access = a.access | b.access;
    u.write = a.write || b.write;
    return u;
}

std::optional<Barrier> transition(ResourceState& s, const Usage& next, bool discard) {
    const bool layout_change = next.layout != VK_IMAGE_LAYOUT_UNDEFINED && next.layout != s.layout;
    const bool had_write = s.write_stages != VK_PIPELINE_STAGE_2_NONE;
    std::optional<Barrier> b;

    if (layout_change || next.write) {
        // A layout transition or a write must wait for everything before it: the last write
        // (made available) and every read since (execution dependency only: write-after-read).
        VkPipelineStageFlags2 src = s.write_stages | s.read_stages;
        if (src != VK_PIPELINE_STAGE_2_NONE || layout_change) {
            b = Barrier{};
            b->old_layout = discard ? VK_IMAGE_LAYOUT_UNDEFINED : s.layout;
            b->new_layout = next.layout == VK_IMAGE_LAYOUT_UNDEFINED ? s.layout : next.layout;
            b->src_stages = src;
            b->src_access = s.write_access & kWriteAccessMask;
            b->dst_stages = next.stages;
            b->dst_access = next.access;
        }
    } else if (had_write && ((next.stages & ~s.visible_stages) || (next.access & ~s.visible_access))) {
        // Read after write, not yet made visible to this stage/access.
        b = Barrier{};
        b->old_layout = s.layout;
        b->new_layout = s.layout;
        b->src_stages = s.write_stages;
        b->src_access = s.write_access & kWriteAccessMask;
        b->dst_stages = next.stages;
        b->dst_access = next.access;
    }

    if (next.layout != VK_IMAGE_LAYOUT_UNDEFINED) s.layout = next.layout;
    if (next.write) {
        s.write_stages = next.stages;
        s.write_access = next.access;
        s.read_stages = VK_PIPELINE_STAGE_2_NONE;
        // The writer's own later reads in the same stage see its writes through the barrier that
        // separates the two uses, so visibility starts empty.
        s.visible_stages = VK_PIPELINE_STAGE_2_NONE;
        s.visible_access = VK_ACCESS_2_NONE;
    } else {
        s.read_stages |= next.stages;
        if (b || !had_write) {
            s.visible_stages |= next.stages;
            s.visible_access |= next.access;
        }
    }
    return b;
}

std::vector<RangeBarrier> transition(ImageState& s, const SubRange& range, const Usage& next, bool discard) {
    std::vector<RangeBarrier> out;
    std::vector<RangeBarrier> prev_level;  // the runs of the previous level, to merge levels
    size_t prev_start = 0;                 // where prev_level's entries start in `out`
    for (uint32_t m = range.mip; m < range.mip + range.mips; ++m) {
        std::vector<RangeBarrier> runs;
        for (uint32_t l = range.layer; l < range.layer + range.layers; ++l) {
            auto b = transition(s.at(m, l), next, discard);
            if (!b) continue;
            if (!runs.empty() && runs.back().barrier == *b && runs.back().range.layer + runs.back().range.layers == l)
                ++runs.back().range.layers;
            else
                runs.push_back({*b, {m, 1, l, 1}});
        }
        auto same_runs = [&] {
            if (runs.size() != prev_level.size() || runs.empty()) return false;
            for (size_t k = 0; k < runs.size(); ++k)
                if (!(runs[k].barrier == prev_level[k].barrier) || runs[k].range.layer != prev_level[k].range.layer ||
                    runs[k].range.layers != prev_level[k].range.layers)
                    return false;
            return out[prev_start].range.mip + out[prev_start].range.mips == m;
        };
        if (same_runs()) {
            for (size_t k = 0; k < runs.size(); ++k) ++out[prev_start + k].range.mips;
        } else {
            prev_start = out.size();
            out.insert(out.end(), runs.begin(), runs.end());
        }
        prev_level = std::move(runs);
    }
    return out;
}

Result<std::vector<size_t>> order_passes(const std::vector<PlanPass>& passes) {
    const size_t n = passes.size();
    // edges[a] = set of b that must run after a; why[(a,b)] = the resource that links them.
    std::vector<std::set<size_t>> edges(n);
    std::map<std::pair<size_t, size_t>, std::string> why;
    auto add_edge = [&](size_t a, size_t b, const std::string& res) {
        if (a == b) return;
        edges[a].insert(b);
        why.emplace(std::make_pair(a, b), res);
    };

    std::map<std::string, std::vector<size_t>> writers;
    for (size_t i = 0; i < n; ++i)
        for (const auto& w : passes[i].writes) {
            auto& v = writers[w];
            if (v.empty() || v.back() != i) v.push_back(i);
        }
    for (auto& [res, ws] : writers)
        for (size_t k = 1; k < ws.size(); ++k) add_edge(ws[k - 1], ws[k], res);

    for (size_t r = 0; r < n; ++r) {
        for (const auto& res : passes[r].reads) {
            auto it = writers.find(res);
            if (it == writers.end()) continue;  // files, generators, history: nobody writes them
            const auto& ws = it->second;
            std::optional<size_t> before, after;
            bool self = false;  // the reader also writes it (atomics, read-modify-write)
            for (size_t w : ws) {
                if (w < r) before = w;
                else if (w > r && !after) after = w;
                self = self || w == r;
            }
            if (before) {
                add_edge(*before, r, res);
                if (after) add_edge(r, *after, res);  // write-after-read
            } else if (after && !self) {
                // Written only later in the file: the writer moves up. (A pass that itself writes
                // the resource is its first writer: file order among the writers stands.)
                add_edge(*after, r, res);
                for (size_t w : ws)
                    if (w > *after) {
                        add_edge(r, w, res);
                        break;
                    }
            }
        }
    }

    // Kahn's algorithm, smallest declaration index first, so unconstrained passes keep file order.
    std::vector<int> indeg(n, 0);
    for (size_t a = 0; a < n; ++a)
        for (size_t b : edges[a]) ++indeg[b];
    std::priority_queue<size_t, std::vector<size_t>, std::greater<>> ready;
    for (size_t i = 0; i < n; ++i)
        if (indeg[i] == 0) ready.push(i);
    std::vector<size_t> order;
    while (!ready.empty()) {
        size_t a = ready.top();
        ready.pop();
        order.push_back(a);
        for (size_t b : edges[a])
            if (--indeg[b] == 0) ready.push(b);
    }
    if (order.size() == n) return order;

    // Find one cycle among the remaining passes to name it.
    std::vector<int> color(n, 0);
    std::vector<size_t> stack;
    std::vector<size_t> cycle;
    std::function<bool(size_t)> dfs = [&](size_t a) {
        color[a] = 1;
        stack.push_back(a);
        for (size_t b : edges[a]) {
            if (indeg[b] == 0 && color[b] == 0) continue;
            if (color[b] == 1) {
                auto it = std::find(stack.begin(), stack.end(), b);
                cycle.assign(it, stack.end());
                return true;
            }
            if (color[b] == 0 && dfs(b)) return true;
        }
        stack.pop_back();
        color[a] = 2;
        return false;
    };
    for (size_t i = 0; i < n && cycle.empty(); ++i)
        if (indeg[i] > 0 && color[i] == 0) dfs(i);

    Error e = make_error("the passes form a cycle: no order satisfies what they read and write",
                         cycle.empty() ? SourceLoc{} : passes[cycle.front()].loc);
    auto label = [&](size_t i) { return std::string(passes[i].group ? "group '" : "pass '") + passes[i].name + "'"; };
    if (!cycle.empty()) {
        if (!passes[cycle.front()].group) e.pass = passes[cycle.front()].name;
        for (size_t k = 0; k < cycle.size(); ++k) {
            size_t a = cycle[k], b = cycle[(k + 1) % cycle.size()];
            e.notes.push_back(label(b) + " (" + passes[b].loc.str() + ") needs '" + why[{a, b}] + "' from " + label(a));
        }
        if (std::any_of(cycle.begin(), cycle.end(), [&](size_t i) { return passes[i].group; }))
            e.notes.push_back("a group runs as one unit: a pass cannot sit between two of its members");
    }
    e.hint = "use a history image (history = true, read as <name>_prev) to read last frame's result";
    return e;
}

} // namespace pl::exec
