#include "exec/resources.hpp"

#include "exec/limits.hpp"

#include "exec/barriers.hpp"
#include "exec/bind.hpp"
#include "exec/mesh_source.hpp"
#include "exec/texels.hpp"
#include "graph/validate.hpp"
#include "image/image.hpp"
#include "scene/mesh.hpp"
#include "scene/scene_buffer.hpp"
#include "vk/check.hpp"
#include "vk/names.hpp"

#include <algorithm>
#include <cmath>
#include <cstring>

namespace pl::exec {

namespace {

Error resource_error(const std::string& msg, const SourceLoc& loc, const std::string& name) {
    Error e = make_error(msg, loc);
    e.resource = name;
    return e;
}

VkFilter filter_of(const std::string& s) { return s == "nearest" ? VK_FILTER_NEAREST : VK_FILTER_LINEAR; }

VkSamplerAddressMode address_of(const std::string& s) {
    if (s == "clamp") return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_EDGE;
    if (s == "mirror") return VK_SAMPLER_ADDRESS_MODE_MIRRORED_REPEAT;
    if (s == "border") return VK_SAMPLER_ADDRESS_MODE_CLAMP_TO_BORDER;
    return VK_SAMPLER_ADDRESS_MODE_REPEAT;
}


// Whether the device can filter `format` linearly when sampled (integer formats never can; depth
// formats often cannot without a compare op).
bool linear_filterable(vk::Context& ctx, VkFormat format) {
    VkFormatProperties fp;
    vkGetPhysicalDeviceFormatProperties(ctx.physical(), format, &fp);
    return (fp.optimalTilingFeatures & VK_FORMAT_FEATURE_SAMPLED_IMAGE_FILTER_LINEAR_BIT) != 0;
}

vk::UniqueSampler make_sampler(vk::Context& ctx, const graph::SamplerDesc& s, const vk::FormatInfo& format) {
    const bool integer = format.is_integer;
    // What the device cannot filter linearly is sampled with nearest filtering (and nearest mip
    // selection, which Vulkan also ties to the linear-filter feature) unless a compare op is set.
    const bool nearest_only = integer || (s.compare.empty() && !linear_filterable(ctx, format.format));
    VkFilter f = nearest_only ? VK_FILTER_NEAREST : filter_of(s.filter);
    VkBorderColor border = VK_BORDER_COLOR_FLOAT_TRANSPARENT_BLACK;
    if (s.border == "opaque_black") border = VK_BORDER_COLOR_FLOAT_OPAQUE_BLACK;
    if (s.border == "opaque_white") border = VK_BORDER_COLOR_FLOAT_OPAQUE_WHITE;
    if (integer) border = static_cast<VkBorderColor>(border + 1);  // the INT variant follows each FLOAT one
    bool aniso = s.anisotropy > 1.0f && ctx.features().sampler_anisotropy && !integer;
    VkSamplerCreateInfo sci{
        .sType = VK_STRUCTURE_TYPE_SAMPLER_CREATE_INFO,
        .magFilter = f,
        .minFilter = f,
        .mipmapMode = (s.mip_filter == "nearest" || nearest_only) ? VK_SAMPLER_MIPMAP_MODE_NEAREST
                                                             : VK_SAMPLER_MIPMAP_MODE_LINEAR,
        .addressModeU = address_of(s.address[0]),
        .addressModeV = address_of(s.address[1]),
        .addressModeW = address_of(s.address[2]),
        .mipLodBias = s.lod_bias,
        .anisotropyEnable = aniso ? VK_TRUE : VK_FALSE,
        .maxAnisotropy = aniso ? std::min(s.anisotropy, ctx.features().max_anisotropy) : 1.0f,
        .compareEnable = s.compare.empty() ? VK_FALSE : VK_TRUE,
        .compareOp = vk::compare_op(s.compare),
        .minLod = s.min_lod,
        .maxLod = s.max_lod,
        .borderColor = border};
    VkSampler smp;
    VK_CHECK(vkCreateSampler(ctx.device(), &sci, nullptr, &smp));
    return vk::UniqueSampler(ctx.device(), smp);
}

struct Needs {
    bool sampled = false, storage = false, attachment = false;
};

Needs direct_needs_of(const CompiledGraph& g, const std::string& name) {
    Needs n;
    auto same = [&](const std::string& other) {
        if (other == name) return true;
        const graph::ImageDesc* d = g.desc.find_image(other);
        return d && d->alias == name;
    };
    for (const auto& cp : g.passes) {
        for (const auto& b : cp.bindings) {
            if (b.kind != BoundResource::Kind::image && b.kind != BoundResource::Kind::image_prev) continue;
            if (!same(b.resource)) continue;
            if (b.binding.type == shader::BindingType::storage_image) n.storage = true;
            else n.sampled = true;
        }
        for (const auto& t : cp.desc->targets)
            if (same(t.image) || same(t.resolve)) n.attachment = true;
        if (cp.desc->depth && same(cp.desc->depth->target.image)) n.attachment = true;
    }
    return n;
}

// An image in a swap pair (a pass's or a group's) takes its partner's role every other
// iteration, so it needs every usage the partner has.
Needs needs_of(const CompiledGraph& g, const std::string& name) {
    Needs n = direct_needs_of(g, name);
    auto partner_of = [&](const std::vector<std::string>& pairs) {
        for (size_t k = 0; k + 1 < pairs.size(); k += 2) {
            const std::string* other = pairs[k] == name ? &pairs[k + 1] : pairs[k + 1] == name ? &pairs[k] : nullptr;
            if (!other) continue;
            Needs o = direct_needs_of(g, *other);
            n.sampled |= o.sampled, n.storage |= o.storage, n.attachment |= o.attachment;
        }
    };
    for (const auto& p : g.desc.passes) partner_of(p.swap);
    for (const auto& gr : g.desc.groups) partner_of(gr.swap);
    return n;
}

// Copies the staging buffer into mip 0 (every layer), then fills the mip chain and leaves the
// image ready for sampling. Barriers come from the planner's transition().
void record_upload(VkCommandBuffer cb, PhysImage& pi, VkBuffer staging) {
    const auto& info = pi.image.info();
    BarrierBatch batch;
    require(batch, pi, usage_of(Access::transfer_dst, 0), true);
    batch.flush(cb);
    VkBufferImageCopy copy{.bufferOffset = 0,
                           .imageSubresource = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 0, info.layers},
                           .imageExtent = info.extent};
    vkCmdCopyBufferToImage(cb, staging, pi.image.handle(), VK_IMAGE_LAYOUT_TRANSFER_DST_OPTIMAL, 1, &copy);
    Usage read = usage_of(Access::sampled, VK_PIPELINE_STAGE_2_ALL_COMMANDS_BIT);
    if (info.mips > 1) {
        record_mip_chain(cb, pi, read);
    } else {
        require(batch, pi, read);
        batch.flush(cb);
    }
    // The final barrier's second scope covers every later command, in this and in later
    // submissions: frames need no further barrier to read the upload.
    for (auto& st : pi.state.sub) {
        st.write_stages = st.read_stages = VK_PIPELINE_STAGE_2_NONE;
        st.write_access = VK_ACCESS_2_NONE;
    }
}

Status upload_pixels(vk::Context& ctx, GraphImage& gi, const image::Image& img) {
    const auto& info = gi.phys[0]->image.info();
    uint32_t texel = static_cast<uint32_t>(gi.format->bytes_per_texel);
    size_t count = static_cast<size_t>(info.extent.width) * info.extent.height * info.extent.depth;
    size_t bytes = count * texel * info.layers;
    vk::Buffer staging = vk::create_buffer(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
    auto* dst = static_cast<uint8_t*>(staging.mapped);
    for (uint32_t l = 0; l < info.layers; ++l)
        for (size_t i = 0; i < count; ++i)
            if (!encode_texel(*gi.format, &img.pixels[i * 4], dst + (l * count + i) * texel))
                return resource_error("image '" + gi.desc->name + "': format " + gi.format->name +
                                          " cannot be filled from a file or generator; use rgba8, "
                                          "rgba8_srgb, rgba16f or rgba32f",
                                      gi.desc->loc, gi.desc->name);
    PhysImage& pi = *gi.phys[0];
    return ctx.run_once([&](VkCommandBuffer cb) { record_upload(cb, pi, staging.buffer); });
}

// generator = "bvh" | "triangles": the words of scene/scene_buffer.hpp over the named meshes.
static_assert(graph::BufferDesc::kMaxLeafSize == scene::kMaxLeafSize, "the parser's leaf_size range is the build's");
Result<std::vector<uint32_t>> generated_words(const graph::BufferDesc& d, const std::map<std::string, CpuMesh>& meshes) {
    std::vector<scene::SceneInput> in;
    for (const auto& name : d.meshes) in.push_back({name, &meshes.at(name).mesh});  // simplified, if asked
    auto words = scene::build_scene_buffer(in, d.generator == "bvh", d.leaf_size);
    if (!words) return resource_error(words.error().message, d.keys.at("generator", d.loc), d.name);
    if (auto s = graph::check_built_buffer_size(d, int64_t(words->size()) * 4); !s) return s.error();
    return words;
}

// Initial contents from `data`: values as 32-bit words, the rest zero.
std::vector<uint32_t> data_words(const graph::BufferDesc& d, VkDeviceSize bytes) {
    std::vector<uint32_t> words(bytes / 4, 0);
    for (size_t i = 0; i < d.data.size() && i < words.size(); ++i) {
        if (d.data_type == "float") {
            float f = static_cast<float>(d.data[i]);
            std::memcpy(&words[i], &f, 4);
        } else if (d.data_type == "int") {
            int32_t v = static_cast<int32_t>(d.data[i]);
            std::memcpy(&words[i], &v, 4);
        } else {
            words[i] = static_cast<uint32_t>(d.data[i]);
        }
    }
    return words;
}

Result<GpuMesh> create_mesh(vk::Context& ctx, const CompiledGraph& g, const graph::MeshDesc& md, const CpuMesh* cpu) {
    const scene::Mesh* mesh = &cpu->mesh;
    GpuMesh gm;
    gm.simplified = cpu->simplified;
    gm.simplify_ms = cpu->simplify_ms;
    if (!cpu->morph.empty()) {  // vertex binding 1: geomorph targets (locations 4..6)
        size_t mb = cpu->morph.size() * sizeof(scene::MorphVertex);
        gm.morph = vk::create_buffer(ctx, mb, VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
        std::memcpy(gm.morph.mapped, cpu->morph.data(), mb);
        gm.has_morph = true;
    }
    size_t vb = mesh->vertices.size() * sizeof(scene::Vertex), ib = mesh->indices.size() * sizeof(uint32_t);
    gm.vertices = vk::create_buffer(ctx, std::max<size_t>(vb, 16), VK_BUFFER_USAGE_VERTEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
    gm.indices = vk::create_buffer(ctx, std::max<size_t>(ib, 16), VK_BUFFER_USAGE_INDEX_BUFFER_BIT | VK_BUFFER_USAGE_STORAGE_BUFFER_BIT, true);
    std::memcpy(gm.vertices.mapped, mesh->vertices.data(), vb);
    std::memcpy(gm.indices.mapped, mesh->indices.data(), ib);
    gm.index_count = static_cast<uint32_t>(mesh->indices.size());
    gm.instances = static_cast<uint32_t>(std::max(1, md.instances));
    bool adjacency = std::any_of(g.desc.passes.begin(), g.desc.passes.end(), [&](const graph::PassDesc& p) {
        return p.mesh == md.name && p.topology == "triangles_adjacency";
    });
    if (adjacency) {
        std::vector<uint32_t> adj = scene::adjacency_indices(*mesh);
        gm.adjacency = vk::create_buffer(ctx, std::max<size_t>(adj.size() * 4, 16), VK_BUFFER_USAGE_INDEX_BUFFER_BIT, true);
        std::memcpy(gm.adjacency.mapped, adj.data(), adj.size() * 4);
        gm.adjacency_count = static_cast<uint32_t>(adj.size());
    }
    return gm;
}

} // namespace

namespace {
// `flip_y`: row 0 of the upload becomes the picture's bottom row (per slice of a 3D image), as
// OpenGL's UNPACK_FLIP_Y does for Shadertoy's vflip.
void flip_rows(image::Image& img) {
    const size_t row = static_cast<size_t>(img.width) * 4;
    for (int z = 0; z < img.depth; ++z)
        for (int y = 0; y < img.height / 2; ++y)
            std::swap_ranges(img.at(0, y, z), img.at(0, y, z) + row, img.at(0, img.height - 1 - y, z));
}
} // namespace

Result<GraphResources> create_resources(vk::Context& ctx, const CompiledGraph& g) {
    GraphResources R;
    graph::SizeEnv env = size_env(g.desc, g.view);
    const VkPhysicalDeviceLimits& limits = ctx.properties().limits;
    const std::string device = ctx.properties().deviceName;
    // Checked before each allocation, so that a graph too large for the device is an error at
    // the resource's key, not VK_ERROR_OUT_OF_DEVICE_MEMORY from inside the driver.
    MemoryBudget budget{ctx.largest_device_heap(), 0, device};

    // Images that own memory first, then aliases pointing at them.
    for (int pass = 0; pass < 2; ++pass) {
        for (const auto& d : g.desc.images) {
            if ((pass == 0) != d.alias.empty()) continue;
            GraphImage gi;
            gi.desc = &d;
            std::string fmt_name = graph::effective_format(g.desc, d);
            gi.format = vk::find_format(fmt_name);
            if (!gi.format) return resource_error("unknown format '" + fmt_name + "'", d.format_loc, d.name);
            if (!d.alias.empty()) {
                const GraphImage& target = R.images.at(d.alias);
                gi.format = target.format;
                gi.extent = target.extent;
                gi.mips = target.mips;
                gi.layers = target.layers;
                gi.phys = target.phys;
                gi.history = target.history;
                gi.sampler = make_sampler(ctx, d.sampler, *gi.format);
                R.images.emplace(d.name, std::move(gi));
                continue;
            }

            // Pixels from a file or generator decide the size of such images.
            std::optional<image::Image> pixels;
            if (!d.file.empty()) {
                auto img = image::load_image(g.desc.dir / d.file);
                if (!img) {
                    Error e = img.error();
                    e.loc = d.loc;
                    e.source_line = read_source_line(d.loc.file, d.loc.line);
                    e.resource = d.name;
                    return e;
                }
                pixels = std::move(img.value());
                gi.extent = {static_cast<uint32_t>(pixels->width), static_cast<uint32_t>(pixels->height), 1};
            } else {
                int dims = d.kind == graph::ImageKind::tex3d ? 3 : 2;
                graph::SizeExpr size = d.size;
                if (size.empty()) {
                    if (d.generator.empty()) size.text = "view";
                    else size.literal = {256, 256};
                }
                auto ext = graph::eval_extent(size, env, dims);
                if (!ext) {
                    Error e = ext.error();
                    e.resource = d.name;
                    return e;
                }
                gi.extent = {static_cast<uint32_t>(ext->w), static_cast<uint32_t>(ext->h),
                             dims == 3 ? static_cast<uint32_t>(ext->d) : 1u};
                if (!d.generator.empty()) {
                    auto img = image::generate_image(d.generator, static_cast<int>(gi.extent.width),
                                                     static_cast<int>(gi.extent.height),
                                                     static_cast<int>(gi.extent.depth), d.generator_args);
                    if (!img) {
                        Error e = img.error();
                        if (!e.loc.known()) e.loc = d.loc;
                        e.resource = d.name;
                        return e;
                    }
                    pixels = std::move(img.value());
                }
            }
            if (pixels && d.flip_y) flip_rows(*pixels);
            uint32_t full = 1 + static_cast<uint32_t>(std::floor(std::log2(std::max({gi.extent.width, gi.extent.height, gi.extent.depth}))));
            gi.mips = d.mips == 0 ? full : std::min(static_cast<uint32_t>(d.mips), full);
            gi.layers = d.kind == graph::ImageKind::cube ? 6u
                        : d.kind == graph::ImageKind::tex2d_array ? static_cast<uint32_t>(std::max(1, d.layers))
                                                                  : 1u;

            Needs need = needs_of(g, d.name);
            vk::ImageInfo info;
            info.format = gi.format->format;
            info.extent = gi.extent;
            info.mips = gi.mips;
            info.layers = gi.layers;
            info.samples = static_cast<VkSampleCountFlagBits>(std::max(1, d.samples));
            info.cube = d.kind == graph::ImageKind::cube;
            info.type = d.kind == graph::ImageKind::tex3d ? VK_IMAGE_TYPE_3D : VK_IMAGE_TYPE_2D;
            info.view_type = d.kind == graph::ImageKind::tex3d       ? VK_IMAGE_VIEW_TYPE_3D
                             : d.kind == graph::ImageKind::cube      ? VK_IMAGE_VIEW_TYPE_CUBE
                             : d.kind == graph::ImageKind::tex2d_array ? VK_IMAGE_VIEW_TYPE_2D_ARRAY
                                                                       : VK_IMAGE_VIEW_TYPE_2D;
            VkFormatProperties fp;
            vkGetPhysicalDeviceFormatProperties(ctx.physical(), info.format, &fp);
            VkFormatFeatureFlags have = fp.optimalTilingFeatures;
            auto require = [&](VkFormatFeatureFlags f, const char* what) -> Status {
                if ((have & f) == f) return ok_status();
                return resource_error("image '" + d.name + "': format " + gi.format->name + " cannot be " +
                                          what + " on this device",
                                      d.format_loc.known() ? d.format_loc : d.loc, d.name);
            };
            info.usage = VK_IMAGE_USAGE_TRANSFER_SRC_BIT | VK_IMAGE_USAGE_TRANSFER_DST_BIT;
            if (have & VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT) info.usage |= VK_IMAGE_USAGE_SAMPLED_BIT;
            else if (need.sampled) {
                if (auto s = require(VK_FORMAT_FEATURE_SAMPLED_IMAGE_BIT, "sampled"); !s) return s.error();
            }
            if (need.storage) {
                if (auto s = require(VK_FORMAT_FEATURE_STORAGE_IMAGE_BIT, "a storage image"); !s) return s.error();
                info.usage |= VK_IMAGE_USAGE_STORAGE_BIT;
            }
            if (gi.format->is_depth) {
                if (auto s = require(VK_FORMAT_FEATURE_DEPTH_STENCIL_ATTACHMENT_BIT, "a depth attachment"); !s) return s.error();
                info.usage |= VK_IMAGE_USAGE_DEPTH_STENCIL_ATTACHMENT_BIT;
            } else if (need.attachment) {
                if (auto s = require(VK_FORMAT_FEATURE_COLOR_ATTACHMENT_BIT, "a render target"); !s) return s.error();
                info.usage |= VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
            }
            gi.history = d.history;
            if (auto s = check_image_limits(limits, device, d, info.extent, info.layers, info.type == VK_IMAGE_TYPE_3D, info.cube); !s)
                return s.error();
            {
                // Texels of every level (a full chain adds a third), layer, sample and history copy.
                double texels = double(info.extent.width) * info.extent.height * info.extent.depth * info.layers * static_cast<double>(info.samples);
                double per_texel = gi.format->compressed() ? gi.format->bytes_per_texel / double(gi.format->block * gi.format->block) : gi.format->bytes_per_texel;
                double bytes = texels * per_texel * (info.mips > 1 ? 4.0 / 3.0 : 1.0) * (d.history ? 2 : 1);
                if (auto s = budget.add(static_cast<VkDeviceSize>(bytes), "image '" + d.name + "'", d.keys.at("size", d.loc), d.name); !s)
                    return s.error();
            }
            for (int k = 0; k < (d.history ? 2 : 1); ++k) {
                auto pi = std::make_shared<PhysImage>();
                pi->image = vk::Image(ctx, info);
                pi->state = ImageState(info.mips, info.layers);
                if (need.storage) {
                    VkImageViewCreateInfo vci{.sType = VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO,
                                              .image = pi->image.handle(),
                                              .viewType = info.view_type,
                                              .format = info.format,
                                              .subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, info.layers}};
                    VkImageView v;
                    VK_CHECK(vkCreateImageView(ctx.device(), &vci, nullptr, &v));
                    pi->storage_view_owner = vk::UniqueImageView(ctx.device(), v);
                    pi->storage_view = v;
                }
                gi.phys[static_cast<size_t>(k)] = pi;
            }
            if (!d.history) gi.phys[1] = gi.phys[0];
            gi.sampler = make_sampler(ctx, d.sampler, *gi.format);
            auto& stored = R.images.emplace(d.name, std::move(gi)).first->second;
            if (pixels) {
                if (stored.extent.depth > 1 && pixels->depth != static_cast<int>(stored.extent.depth))
                    return resource_error("image '" + d.name + "': generator produced a 2D image for a 3D size", d.loc, d.name);
                if (auto s = upload_pixels(ctx, stored, *pixels); !s) return s.error();
            }
        }
    }

    // CPU meshes once: draws upload them, host-built buffers are built from them.
    std::map<std::string, CpuMesh> cpu_meshes;
    for (const auto& md : g.desc.meshes) {
        auto m = load_graph_mesh(g.desc, md);
        if (!m) return m.error();
        cpu_meshes.emplace(md.name, std::move(m.value()));
    }

    for (const auto& d : g.desc.buffers) {
        GraphBuffer gb;
        gb.desc = &d;
        std::vector<uint32_t> words;
        if (!d.generator.empty()) {
            auto w = generated_words(d, cpu_meshes);
            if (!w) return w.error();
            words = std::move(w.value());
        } else {
            auto size = graph::eval_scalar(d.size, env);
            if (!size) {
                Error e = size.error();
                e.resource = d.name;
                return e;
            }
            const VkDeviceSize rounded = (static_cast<VkDeviceSize>(*size) + 3) / 4 * 4;
            if (auto s = budget.add(rounded * (d.history ? 2 : 1), "buffer '" + d.name + "'", d.keys.at("size", d.loc), d.name); !s)
                return s.error();
            words = data_words(d, rounded);
        }
        const VkDeviceSize bytes = words.size() * 4;
        VkBufferUsageFlags usage = VK_BUFFER_USAGE_STORAGE_BUFFER_BIT | VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT |
                                   VK_BUFFER_USAGE_INDIRECT_BUFFER_BIT | VK_BUFFER_USAGE_TRANSFER_SRC_BIT |
                                   VK_BUFFER_USAGE_TRANSFER_DST_BIT | VK_BUFFER_USAGE_VERTEX_BUFFER_BIT |
                                   VK_BUFFER_USAGE_INDEX_BUFFER_BIT;
        vk::Buffer staging = vk::create_buffer(ctx, bytes, VK_BUFFER_USAGE_TRANSFER_SRC_BIT, true);
        std::memcpy(staging.mapped, words.data(), bytes);
        for (int k = 0; k < (d.history ? 2 : 1); ++k) {
            auto pb = std::make_shared<PhysBuffer>();
            pb->buffer = vk::create_buffer(ctx, bytes, usage, false);
            VkBuffer dst = pb->buffer.buffer;
            if (auto s = ctx.run_once([&](VkCommandBuffer cb) {
                    VkBufferCopy c{0, 0, bytes};
                    vkCmdCopyBuffer(cb, staging.buffer, dst, 1, &c);
                });
                !s)
                return s.error();
            pb->state.write_stages = VK_PIPELINE_STAGE_2_ALL_TRANSFER_BIT;
            pb->state.write_access = VK_ACCESS_2_TRANSFER_WRITE_BIT;
            gb.phys[static_cast<size_t>(k)] = pb;
        }
        if (!d.history) gb.phys[1] = gb.phys[0];
        gb.history = d.history;
        R.buffers.emplace(d.name, std::move(gb));
    }

    for (const auto& md : g.desc.meshes) {
        auto m = create_mesh(ctx, g, md, &cpu_meshes.at(md.name));
        if (!m) return m.error();
        R.meshes.emplace(md.name, std::move(m.value()));
    }
    return R;
}

} // namespace pl::exec
