#include "exec/limits.hpp"

#include "graph/validate_parts.hpp"

namespace pl::exec {

Status check_binding_limits(const VkPhysicalDeviceLimits& lim, const std::string& device, const CompiledGraph& g,
                            const std::map<std::string, VkDeviceSize>& sizes) {
    for (const auto& cp : g.passes) {
        for (const auto& b : cp.bindings) {
            if (b.kind != BoundResource::Kind::buffer && b.kind != BoundResource::Kind::buffer_prev) continue;
            auto it = sizes.find(b.resource);
            const graph::BufferDesc* d = g.desc.find_buffer(b.resource);
            if (it == sizes.end() || !d) continue;
            const bool uniform = b.binding.type == shader::BindingType::uniform_buffer;
            const VkDeviceSize size = it->second;
            const VkDeviceSize limit = uniform ? lim.maxUniformBufferRange : lim.maxStorageBufferRange;
            if (size <= limit) continue;
            Error e = make_error("buffer '" + d->name + "' is " + std::to_string(size) + " bytes (" + graph::human_bytes(double(size)) +
                                     "), more than this device binds as a " + (uniform ? "uniform" : "storage") + " buffer: " +
                                     (uniform ? "maxUniformBufferRange" : "maxStorageBufferRange") + " = " + std::to_string(limit) +
                                     " bytes (" + graph::human_bytes(double(limit)) + ") on " + device,
                                 d->keys.at(d->generator.empty() ? "size" : "generator", d->loc));  // a built buffer has no size key
            e.pass = cp.desc->name;
            e.resource = d->name;
            e.hint = uniform ? "declare the block as a storage buffer (buffer { ... }), whose limit is higher"
                             : "split the data over several buffers, or make it smaller";
            return e;
        }
    }
    return ok_status();
}

} // namespace pl::exec
