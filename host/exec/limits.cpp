#include "exec/limits.hpp"

#include "graph/validate_parts.hpp"

namespace pl::exec {

namespace {

// "200000000 bytes (190.7 MiB)"; below a MiB the exact count says it all ("65536 bytes").
std::string bytes_text(VkDeviceSize n) {
    std::string exact = std::to_string(n) + " bytes";
    return n >= (VkDeviceSize(1) << 20) ? exact + " (" + graph::human_bytes(double(n)) + ")" : exact;
}

} // namespace

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
            Error e = make_error("buffer '" + d->name + "' is " + bytes_text(size) + ", more than this device binds as a " +
                                     (uniform ? "uniform" : "storage") + " buffer: " + (uniform ? "maxUniformBufferRange" : "maxStorageBufferRange") +
                                     " = " + bytes_text(limit) + " on " + device,
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
