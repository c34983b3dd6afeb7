#include "exec/limits.hpp"

#include "graph/validate_parts.hpp"

#include <algorithm>

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

Status check_image_limits(const VkPhysicalDeviceLimits& lim, const std::string& device, const graph::ImageDesc& d,
                          VkExtent3D e, uint32_t layers, bool is_3d, bool is_cube) {
    const uint32_t side = is_3d ? lim.maxImageDimension3D : is_cube ? lim.maxImageDimensionCube : lim.maxImageDimension2D;
    const char* name = is_3d ? "maxImageDimension3D" : is_cube ? "maxImageDimensionCube" : "maxImageDimension2D";
    const uint32_t largest = std::max({e.width, e.height, is_3d ? e.depth : 1u});
    if (largest > side) {
        Error err = make_error("image '" + d.name + "' is " + std::to_string(e.width) + "x" + std::to_string(e.height) +
                                   (is_3d ? "x" + std::to_string(e.depth) : "") + ", larger than this device's " + name + " = " +
                                   std::to_string(side) + " on " + device,
                               d.keys.at("size", d.loc));
        err.resource = d.name;
        err.hint = "make it smaller (--size, or the image's size expression)";
        return err;
    }
    if (!is_3d && layers > lim.maxImageArrayLayers) {
        Error err = make_error("image '" + d.name + "' has " + std::to_string(layers) + " layers, more than maxImageArrayLayers = " +
                                   std::to_string(lim.maxImageArrayLayers) + " on " + device,
                               d.keys.at("layers", d.loc));
        err.resource = d.name;
        return err;
    }
    return ok_status();
}

Status check_compute_limits(const VkPhysicalDeviceLimits& lim, const std::string& device, const CompiledGraph& g) {
    for (const auto& cp : g.passes) {
        const shader::Reflection& r = cp.program.reflection;
        if (cp.desc->compute.empty()) continue;
        const SourceLoc shader_loc{cp.desc->compute.file, 0, 0};
        uint64_t invocations = uint64_t(r.local_size[0]) * r.local_size[1] * r.local_size[2];
        for (int k = 0; k < 3; ++k)
            if (r.local_size[k] > lim.maxComputeWorkGroupSize[k]) {
                Error e = make_error("pass '" + cp.desc->name + "': local_size_" + std::string(1, char('x' + k)) + " = " +
                                         std::to_string(r.local_size[k]) + " exceeds maxComputeWorkGroupSize[" + std::to_string(k) +
                                         "] = " + std::to_string(lim.maxComputeWorkGroupSize[k]) + " on " + device,
                                     cp.desc->compute.loc.known() ? cp.desc->compute.loc : shader_loc);
                e.pass = cp.desc->name;
                return e;
            }
        if (invocations > lim.maxComputeWorkGroupInvocations) {
            Error e = make_error("pass '" + cp.desc->name + "': a workgroup of " + std::to_string(invocations) +
                                     " invocations exceeds maxComputeWorkGroupInvocations = " +
                                     std::to_string(lim.maxComputeWorkGroupInvocations) + " on " + device,
                                 cp.desc->compute.loc.known() ? cp.desc->compute.loc : shader_loc);
            e.pass = cp.desc->name;
            e.hint = "use a smaller local_size (and more groups)";
            return e;
        }
        if (r.shared_bytes > lim.maxComputeSharedMemorySize) {
            Error e = make_error("pass '" + cp.desc->name + "': the compute shader declares " + std::to_string(r.shared_bytes) +
                                     " bytes of shared memory, more than maxComputeSharedMemorySize = " +
                                     std::to_string(lim.maxComputeSharedMemorySize) + " on " + device,
                                 r.shared_decl.known() ? r.shared_decl : shader_loc);
            if (r.shared_decl.known()) e.source_line = read_source_line(r.shared_decl.file, r.shared_decl.line);
            e.pass = cp.desc->name;
            e.hint = "a large array shared by the workgroup belongs in a storage buffer ([buffers])";
            return e;
        }
    }
    return ok_status();
}

Status MemoryBudget::add(VkDeviceSize bytes, const std::string& what, const SourceLoc& loc, const std::string& resource) {
    used = used + bytes < used ? ~VkDeviceSize(0) : used + bytes;
    if (heap == 0 || used <= heap) return ok_status();
    Error e = make_error(what + " needs " + bytes_text(bytes) + "; with the resources before it the graph needs " + bytes_text(used) +
                             ", more than the largest memory heap of " + device + " (" + bytes_text(heap) + ")",
                         loc);
    e.resource = resource;
    e.code = ExitCode::environment;
    e.hint = "make the images or buffers smaller (--size, size expressions)";
    return e;
}

} // namespace pl::exec
