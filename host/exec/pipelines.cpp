#include "exec/pipelines.hpp"

#include "exec/cameras.hpp"

#include "scene/mesh.hpp"
#include "scene/simplify.hpp"
#include "vk/check.hpp"
#include "vk/names.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <type_traits>

namespace pl::exec {

using shader::Stage;

VkPipelineStageFlags2 pipeline_stages(uint32_t bits) {
    VkPipelineStageFlags2 f = VK_PIPELINE_STAGE_2_NONE;
    auto has = [&](Stage s) { return (bits >> static_cast<int>(s)) & 1u; };
    if (has(Stage::vertex)) f |= VK_PIPELINE_STAGE_2_VERTEX_SHADER_BIT;
    if (has(Stage::tess_control)) f |= VK_PIPELINE_STAGE_2_TESSELLATION_CONTROL_SHADER_BIT;
    if (has(Stage::tess_eval)) f |= VK_PIPELINE_STAGE_2_TESSELLATION_EVALUATION_SHADER_BIT;
    if (has(Stage::geometry)) f |= VK_PIPELINE_STAGE_2_GEOMETRY_SHADER_BIT;
    if (has(Stage::fragment)) f |= VK_PIPELINE_STAGE_2_FRAGMENT_SHADER_BIT;
    if (has(Stage::compute)) f |= VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT;
    return f;
}

VkShaderStageFlags vk_stages(uint32_t bits) {
    VkShaderStageFlags f = 0;
    auto has = [&](Stage s) { return (bits >> static_cast<int>(s)) & 1u; };
    if (has(Stage::vertex)) f |= VK_SHADER_STAGE_VERTEX_BIT;
    if (has(Stage::tess_control)) f |= VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
    if (has(Stage::tess_eval)) f |= VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
    if (has(Stage::geometry)) f |= VK_SHADER_STAGE_GEOMETRY_BIT;
    if (has(Stage::fragment)) f |= VK_SHADER_STAGE_FRAGMENT_BIT;
    if (has(Stage::compute)) f |= VK_SHADER_STAGE_COMPUTE_BIT;
    return f;
}

namespace {

VkShaderStageFlagBits vk_stage(Stage s) {
    switch (s) {
    case Stage::vertex: return VK_SHADER_STAGE_VERTEX_BIT;
    case Stage::tess_control: return VK_SHADER_STAGE_TESSELLATION_CONTROL_BIT;
    case Stage::tess_eval: return VK_SHADER_STAGE_TESSELLATION_EVALUATION_BIT;
    case Stage::geometry: return VK_SHADER_STAGE_GEOMETRY_BIT;
    case Stage::fragment: return VK_SHADER_STAGE_FRAGMENT_BIT;
    case Stage::compute: return VK_SHADER_STAGE_COMPUTE_BIT;
    }
    return VK_SHADER_STAGE_ALL;
}

VkDescriptorType descriptor_type_impl(shader::BindingType t) {
    switch (t) {
    case shader::BindingType::uniform_buffer: return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
    case shader::BindingType::storage_buffer: return VK_DESCRIPTOR_TYPE_STORAGE_BUFFER;
    case shader::BindingType::combined_image_sampler: return VK_DESCRIPTOR_TYPE_COMBINED_IMAGE_SAMPLER;
    case shader::BindingType::sampled_image: return VK_DESCRIPTOR_TYPE_SAMPLED_IMAGE;
    case shader::BindingType::storage_image: return VK_DESCRIPTOR_TYPE_STORAGE_IMAGE;
    case shader::BindingType::sampler: return VK_DESCRIPTOR_TYPE_SAMPLER;
    }
    return VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER;
}

VkBlendFactor blend_factor(const std::string& s) {
    static const std::map<std::string, VkBlendFactor> m = {
        {"zero", VK_BLEND_FACTOR_ZERO},
        {"one", VK_BLEND_FACTOR_ONE},
        {"src_color", VK_BLEND_FACTOR_SRC_COLOR},
        {"one_minus_src_color", VK_BLEND_FACTOR_ONE_MINUS_SRC_COLOR},
        {"dst_color", VK_BLEND_FACTOR_DST_COLOR},
        {"one_minus_dst_color", VK_BLEND_FACTOR_ONE_MINUS_DST_COLOR},
        {"src_alpha", VK_BLEND_FACTOR_SRC_ALPHA},
        {"one_minus_src_alpha", VK_BLEND_FACTOR_ONE_MINUS_SRC_ALPHA},
        {"dst_alpha", VK_BLEND_FACTOR_DST_ALPHA},
        {"one_minus_dst_alpha", VK_BLEND_FACTOR_ONE_MINUS_DST_ALPHA},
        {"constant_color", VK_BLEND_FACTOR_CONSTANT_COLOR},
        {"src_alpha_saturate", VK_BLEND_FACTOR_SRC_ALPHA_SATURATE},
    };
    auto it = m.find(s);
    return it == m.end() ? VK_BLEND_FACTOR_ONE : it->second;
}

VkBlendOp blend_op(const std::string& s) {
    if (s == "subtract") return VK_BLEND_OP_SUBTRACT;
    if (s == "reverse_subtract") return VK_BLEND_OP_REVERSE_SUBTRACT;
    if (s == "min") return VK_BLEND_OP_MIN;
    if (s == "max") return VK_BLEND_OP_MAX;
    return VK_BLEND_OP_ADD;
}


VkStencilOp stencil_op(const std::string& s) {
    if (s == "zero") return VK_STENCIL_OP_ZERO;
    if (s == "replace") return VK_STENCIL_OP_REPLACE;
    if (s == "increment_clamp" || s == "incr") return VK_STENCIL_OP_INCREMENT_AND_CLAMP;
    if (s == "decrement_clamp" || s == "decr") return VK_STENCIL_OP_DECREMENT_AND_CLAMP;
    if (s == "invert") return VK_STENCIL_OP_INVERT;
    if (s == "increment_wrap" || s == "incr_wrap") return VK_STENCIL_OP_INCREMENT_AND_WRAP;
    if (s == "decrement_wrap" || s == "decr_wrap") return VK_STENCIL_OP_DECREMENT_AND_WRAP;
    return VK_STENCIL_OP_KEEP;
}

VkStencilOpState stencil_face(const graph::StencilFaceDesc& f, const graph::StencilDesc& s) {
    return {stencil_op(f.fail), stencil_op(f.pass), stencil_op(f.depth_fail), vk::compare_op(f.compare),
            s.read_mask, s.write_mask, s.reference};
}

VkPrimitiveTopology topology_of(const std::string& t) {
    if (t == "triangle_strip") return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_STRIP;
    if (t == "lines") return VK_PRIMITIVE_TOPOLOGY_LINE_LIST;
    if (t == "line_strip") return VK_PRIMITIVE_TOPOLOGY_LINE_STRIP;
    if (t == "points") return VK_PRIMITIVE_TOPOLOGY_POINT_LIST;
    if (t == "patches") return VK_PRIMITIVE_TOPOLOGY_PATCH_LIST;
    if (t == "triangles_adjacency") return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST_WITH_ADJACENCY;
    return VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST;
}

VkColorComponentFlags write_mask(const std::string& m) {
    VkColorComponentFlags f = 0;
    if (m.find('r') != std::string::npos) f |= VK_COLOR_COMPONENT_R_BIT;
    if (m.find('g') != std::string::npos) f |= VK_COLOR_COMPONENT_G_BIT;
    if (m.find('b') != std::string::npos) f |= VK_COLOR_COMPONENT_B_BIT;
    if (m.find('a') != std::string::npos) f |= VK_COLOR_COMPONENT_A_BIT;
    return f;
}

} // namespace

VkDescriptorType descriptor_type(shader::BindingType t) { return descriptor_type_impl(t); }

Error pass_error(const graph::PassDesc& pd, const std::string& msg) {
    Error e = make_error(msg, pd.loc);
    e.pass = pd.name;
    return e;
}

namespace {

// Appends the raw bytes of plain (pointer-free) values to a cache key.
template <class T> void put(std::string& key, const T& v) {
    static_assert(std::is_trivially_copyable_v<T>);
    key.append(reinterpret_cast<const char*>(&v), sizeof v);
}
template <class T> void put_all(std::string& key, const std::vector<T>& v) {
    put(key, v.size());
    if (!v.empty()) key.append(reinterpret_cast<const char*>(v.data()), v.size() * sizeof(T));
}

} // namespace

std::shared_ptr<PassPipeline> PipelineCache::find(const std::string& key) {
    // Drop what no executor uses any more, so the map stays as small as the live pipelines.
    for (auto it = entries_.begin(); it != entries_.end();) it = it->second.expired() ? entries_.erase(it) : std::next(it);
    auto it = entries_.find(key);
    return it == entries_.end() ? nullptr : it->second.lock();
}

void PipelineCache::insert(const std::string& key, const std::shared_ptr<PassPipeline>& p) { entries_[key] = p; }

Result<std::shared_ptr<PassPipeline>> create_pass_pipeline(vk::Context& ctx, const CompiledGraph& g, const CompiledPass& cp,
                                                           const GraphResources& res, PipelineCache* cache, bool* reused) {
    auto pp_owner = std::make_shared<PassPipeline>();
    PassPipeline& pp = *pp_owner;
    if (reused) *reused = false;
    const graph::PassDesc& pd = *cp.desc;
    if (cp.program.stages.empty()) return pp_owner;
    VkDevice dev = ctx.device();

    // Descriptor set layouts from reflection, one per set index used.
    std::map<uint32_t, std::vector<VkDescriptorSetLayoutBinding>> sets;
    for (const auto& b : cp.program.reflection.bindings)
        sets[b.set].push_back({b.binding, descriptor_type(b.type), b.count, vk_stages(b.stages), nullptr});
    uint32_t nsets = sets.empty() ? 0 : sets.rbegin()->first + 1;
    VkPushConstantRange pcr{};
    const auto& refl = cp.program.reflection;
    if (refl.push_constant_size > 0) {
        pp.push_stages = vk_stages(refl.push_constant_stages);
        pcr = {pp.push_stages, 0, refl.push_constant_size};
    }
    // The cache key starts with the layout and the code; the raster state follows below.
    std::string key;
    put(key, pd.kind);
    for (uint32_t s = 0; s < nsets; ++s) {
        put(key, s);
        for (const auto& b : sets[s]) put(key, std::array<uint32_t, 4>{b.binding, uint32_t(b.descriptorType), b.descriptorCount, b.stageFlags});
    }
    put(key, pcr);
    for (const auto& st : cp.program.stages) {
        put(key, st.stage);
        put_all(key, st.words);
    }
    // Creates what the key describes, or shares the cached pipeline.
    auto finish = [&](auto&& create_pipeline) -> Result<std::shared_ptr<PassPipeline>> {
        if (cache)
            if (auto hit = cache->find(key)) {
                if (reused) *reused = true;
                return hit;
            }
        std::vector<VkDescriptorSetLayout> raw_layouts;
        for (uint32_t s = 0; s < nsets; ++s) {
            auto& v = sets[s];
            VkDescriptorSetLayoutCreateInfo ci{.sType = VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                               .bindingCount = static_cast<uint32_t>(v.size()),
                                               .pBindings = v.data()};
            VkDescriptorSetLayout l;
            VK_CHECK(vkCreateDescriptorSetLayout(dev, &ci, nullptr, &l));
            pp.set_layouts.emplace_back(dev, l);
            raw_layouts.push_back(l);
        }
        VkPipelineLayoutCreateInfo lci{.sType = VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO,
                                       .setLayoutCount = static_cast<uint32_t>(raw_layouts.size()),
                                       .pSetLayouts = raw_layouts.data(),
                                       .pushConstantRangeCount = refl.push_constant_size > 0 ? 1u : 0u,
                                       .pPushConstantRanges = &pcr};
        VkPipelineLayout layout;
        VK_CHECK(vkCreatePipelineLayout(dev, &lci, nullptr, &layout));
        pp.layout = vk::UniquePipelineLayout(dev, layout);
        std::vector<vk::UniqueShaderModule> modules;
        std::vector<VkPipelineShaderStageCreateInfo> stages;
        for (const auto& st : cp.program.stages) {
            VkShaderModuleCreateInfo mci{.sType = VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO,
                                         .codeSize = st.words.size() * 4,
                                         .pCode = st.words.data()};
            VkShaderModule m;
            VK_CHECK(vkCreateShaderModule(dev, &mci, nullptr, &m));
            modules.emplace_back(dev, m);
            stages.push_back({.sType = VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                              .stage = vk_stage(st.stage),
                              .module = m,
                              .pName = "main"});
        }
        VkPipeline p;
        VK_CHECK(create_pipeline(layout, stages, &p));
        pp.pipeline = vk::UniquePipeline(dev, p);
        if (cache) cache->insert(key, pp_owner);
        return pp_owner;
    };

    if (pd.kind == graph::PassKind::compute) {
        pp.bind_point = VK_PIPELINE_BIND_POINT_COMPUTE;
        return finish([&](VkPipelineLayout layout, const std::vector<VkPipelineShaderStageCreateInfo>& stages, VkPipeline* p) {
            VkComputePipelineCreateInfo ci{.sType = VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO, .stage = stages[0], .layout = layout};
            return vkCreateComputePipelines(dev, VK_NULL_HANDLE, 1, &ci, nullptr, p);
        });
    }

    // --- graphics ---
    std::vector<VkFormat> color_formats;
    VkSampleCountFlagBits samples = VK_SAMPLE_COUNT_1_BIT;
    bool samples_set = false;
    auto check_samples = [&](const GraphImage& gi) -> Status {
        auto s = static_cast<VkSampleCountFlagBits>(std::max(1, gi.desc->samples));
        if (samples_set && s != samples)
            return pass_error(pd, "the pass's attachments have different sample counts");
        samples = s;
        samples_set = true;
        return ok_status();
    };
    for (const auto& t : pd.targets) {
        const GraphImage& gi = res.images.at(t.image);
        color_formats.push_back(gi.format->format);
        if (auto s = check_samples(gi); !s) return s.error();
    }
    VkFormat depth_format = VK_FORMAT_UNDEFINED, stencil_format = VK_FORMAT_UNDEFINED;
    if (pd.depth) {
        const GraphImage& gi = res.images.at(pd.depth->target.image);
        depth_format = gi.format->format;
        if (gi.format->has_stencil) stencil_format = depth_format;
        if (auto s = check_samples(gi); !s) return s.error();
    }
    if (refl.fragment_output_count > color_formats.size())
        return pass_error(pd, "the fragment shader writes " + std::to_string(refl.fragment_output_count) +
                                  " colour outputs but the pass has " + std::to_string(color_formats.size()) +
                                  " target(s)");

    // Vertex input: the mesh's interleaved layout, only the locations the shader reads; binding 1
    // holds a simplified mesh's geomorph targets (scene::MorphVertex), locations 4..6.
    std::vector<VkVertexInputAttributeDescription> attrs;
    std::vector<VkVertexInputBindingDescription> vbinds;
    if (!pd.mesh.empty()) {
        bool morph = false;
        for (uint32_t loc : refl.vertex_input_locations) {
            switch (loc) {
            case 0: attrs.push_back({0, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, position)}); break;
            case 1: attrs.push_back({1, 0, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::Vertex, normal)}); break;
            case 2: attrs.push_back({2, 0, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::Vertex, uv)}); break;
            case 3: attrs.push_back({3, 0, VK_FORMAT_R32G32B32A32_SFLOAT, offsetof(scene::Vertex, tangent)}); break;
            case 4: attrs.push_back({4, 1, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::MorphVertex, position)}), morph = true; break;
            case 5: attrs.push_back({5, 1, VK_FORMAT_R32G32B32_SFLOAT, offsetof(scene::MorphVertex, normal)}), morph = true; break;
            case 6: attrs.push_back({6, 1, VK_FORMAT_R32G32_SFLOAT, offsetof(scene::MorphVertex, uv)}), morph = true; break;
            default:
                return pass_error(pd, "vertex shader input location " + std::to_string(loc) +
                                          " does not exist; meshes provide 0 position, 1 normal, 2 uv, 3 tangent, and "
                                          "with simplify.morph 4 morph_position, 5 morph_normal, 6 morph_uv");
            }
        }
        if (morph && !res.meshes.at(pd.mesh).has_morph) {
            Error e = pass_error(pd, "the vertex shader reads geomorph inputs (locations 4..6) but mesh '" + pd.mesh +
                                         "' has none");
            e.loc = pd.keys.at("mesh", e.loc);  // the mesh named here is the one lacking them
            e.resource = pd.mesh;
            e.hint = "give the mesh simplify = { ratio = ..., morph = { ratio = <coarser> } }";
            return e;
        }
        if (!attrs.empty()) vbinds.push_back({0, sizeof(scene::Vertex), VK_VERTEX_INPUT_RATE_VERTEX});
        if (morph) vbinds.push_back({1, sizeof(scene::MorphVertex), VK_VERTEX_INPUT_RATE_VERTEX});
    } else if (!refl.vertex_input_locations.empty()) {
        return pass_error(pd, "the vertex shader reads vertex inputs but the pass has no mesh");
    }
    VkPipelineVertexInputStateCreateInfo vi{.sType = VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO,
                                            .vertexBindingDescriptionCount = static_cast<uint32_t>(vbinds.size()),
                                            .pVertexBindingDescriptions = vbinds.data(),
                                            .vertexAttributeDescriptionCount = static_cast<uint32_t>(attrs.size()),
                                            .pVertexAttributeDescriptions = attrs.data()};
    bool fullscreen = pd.kind == graph::PassKind::fullscreen;
    VkPipelineInputAssemblyStateCreateInfo ia{.sType = VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO,
                                              .topology = fullscreen ? VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST
                                                                     : topology_of(pd.topology)};
    VkPipelineTessellationStateCreateInfo ts{.sType = VK_STRUCTURE_TYPE_PIPELINE_TESSELLATION_STATE_CREATE_INFO,
                                             .patchControlPoints = static_cast<uint32_t>(std::max(1, pd.patch_points))};
    VkPipelineViewportStateCreateInfo vps{.sType = VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO,
                                          .viewportCount = 1,
                                          .scissorCount = 1};
    VkCullModeFlags cull = fullscreen || pd.cull == "none" ? VK_CULL_MODE_NONE
                           : pd.cull == "front"            ? VK_CULL_MODE_FRONT_BIT
                                                           : VK_CULL_MODE_BACK_BIT;
    bool bias = pd.depth && (pd.depth->bias_constant != 0.0f || pd.depth->bias_slope != 0.0f);
    VkPipelineRasterizationStateCreateInfo rs{
        .sType = VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO,
        .depthClampEnable = pd.depth && pd.depth->clamp && ctx.features().depth_clamp,
        .polygonMode = pd.polygon == "line"    ? VK_POLYGON_MODE_LINE
                       : pd.polygon == "point" ? VK_POLYGON_MODE_POINT
                                               : VK_POLYGON_MODE_FILL,
        .cullMode = cull,
        // Our projection flips y (see scene/camera.hpp), which keeps CCW-from-outside meshes
        // counter-clockwise in framebuffer space. A cube camera's faces are mirror images (the
        // cube-map convention), so its passes get the opposite front face and cull as written.
        .frontFace = (pd.front_face == "cw") != renders_cube_faces(g.desc, pd) ? VK_FRONT_FACE_CLOCKWISE
                                                                             : VK_FRONT_FACE_COUNTER_CLOCKWISE,
        .depthBiasEnable = bias,
        .depthBiasConstantFactor = bias ? pd.depth->bias_constant : 0.0f,
        .depthBiasSlopeFactor = bias ? pd.depth->bias_slope : 0.0f,
        .lineWidth = ctx.features().wide_lines ? pd.line_width : 1.0f};
    if (pd.polygon != "fill" && !ctx.features().fill_mode_non_solid)
        return pass_error(pd, "polygon = \"" + pd.polygon + "\" needs fillModeNonSolid, which this device lacks");
    VkPipelineMultisampleStateCreateInfo ms{.sType = VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO,
                                            .rasterizationSamples = samples};
    VkPipelineDepthStencilStateCreateInfo ds{.sType = VK_STRUCTURE_TYPE_PIPELINE_DEPTH_STENCIL_STATE_CREATE_INFO};
    if (pd.depth) {
        ds.depthTestEnable = pd.depth->test != "off";
        ds.depthWriteEnable = pd.depth->write;
        ds.depthCompareOp = pd.depth->test == "off" ? VK_COMPARE_OP_ALWAYS : vk::compare_op(pd.depth->test);
    }
    if (pd.stencil.enable) {
        ds.stencilTestEnable = VK_TRUE;
        ds.front = stencil_face(pd.stencil.front, pd.stencil);
        ds.back = stencil_face(pd.stencil.back, pd.stencil);
    }
    std::vector<VkPipelineColorBlendAttachmentState> blends;
    for (size_t i = 0; i < color_formats.size(); ++i) {
        graph::BlendDesc b = pd.blend.empty() ? graph::BlendDesc{}
                                              : pd.blend[std::min(i, pd.blend.size() - 1)];
        const vk::FormatInfo* fi = vk::find_format(color_formats[i]);
        if (b.enable && fi && fi->is_integer)
            return pass_error(pd, "blending is not possible on integer target '" + pd.targets[i].image + "'");
        blends.push_back({.blendEnable = b.enable,
                          .srcColorBlendFactor = blend_factor(b.src_color),
                          .dstColorBlendFactor = blend_factor(b.dst_color),
                          .colorBlendOp = blend_op(b.color_op),
                          .srcAlphaBlendFactor = blend_factor(b.src_alpha),
                          .dstAlphaBlendFactor = blend_factor(b.dst_alpha),
                          .alphaBlendOp = blend_op(b.alpha_op),
                          .colorWriteMask = write_mask(b.write_mask)});
    }
    if (pd.blend.size() > 1 && !ctx.features().independent_blend)
        return pass_error(pd, "per-target blend states need independentBlend, which this device lacks");
    VkPipelineColorBlendStateCreateInfo cbs{.sType = VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO,
                                            .attachmentCount = static_cast<uint32_t>(blends.size()),
                                            .pAttachments = blends.data()};
    VkDynamicState dyn[] = {VK_DYNAMIC_STATE_VIEWPORT, VK_DYNAMIC_STATE_SCISSOR};
    VkPipelineDynamicStateCreateInfo dys{.sType = VK_STRUCTURE_TYPE_PIPELINE_DYNAMIC_STATE_CREATE_INFO,
                                         .dynamicStateCount = 2,
                                         .pDynamicStates = dyn};
    VkPipelineRenderingCreateInfo rci{.sType = VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO,
                                      .colorAttachmentCount = static_cast<uint32_t>(color_formats.size()),
                                      .pColorAttachmentFormats = color_formats.data(),
                                      .depthAttachmentFormat = depth_format,
                                      .stencilAttachmentFormat = stencil_format};
    bool tess = std::any_of(cp.program.stages.begin(), cp.program.stages.end(),
                            [](const shader::StageSpirv& s) { return s.stage == Stage::tess_control; });
    // The rest of the key: every state value below, as the create-info will carry it.
    put_all(key, color_formats);
    put(key, std::array<VkFormat, 2>{depth_format, stencil_format});
    put_all(key, attrs);
    put_all(key, vbinds);
    put(key, std::array<uint32_t, 4>{uint32_t(ia.topology), ts.patchControlPoints, uint32_t(tess), uint32_t(samples)});
    put(key, std::array<uint32_t, 5>{rs.depthClampEnable, uint32_t(rs.polygonMode), rs.cullMode, uint32_t(rs.frontFace), rs.depthBiasEnable});
    put(key, std::array<float, 3>{rs.depthBiasConstantFactor, rs.depthBiasSlopeFactor, rs.lineWidth});
    put(key, std::array<uint32_t, 4>{ds.depthTestEnable, ds.depthWriteEnable, uint32_t(ds.depthCompareOp), ds.stencilTestEnable});
    put(key, ds.front);
    put(key, ds.back);
    put_all(key, blends);
    return finish([&](VkPipelineLayout layout, const std::vector<VkPipelineShaderStageCreateInfo>& stages, VkPipeline* p) {
        VkGraphicsPipelineCreateInfo gci{.sType = VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO,
                                         .pNext = &rci,
                                         .stageCount = static_cast<uint32_t>(stages.size()),
                                         .pStages = stages.data(),
                                         .pVertexInputState = &vi,
                                         .pInputAssemblyState = &ia,
                                         .pTessellationState = tess ? &ts : nullptr,
                                         .pViewportState = &vps,
                                         .pRasterizationState = &rs,
                                         .pMultisampleState = &ms,
                                         .pDepthStencilState = &ds,
                                         .pColorBlendState = &cbs,
                                         .pDynamicState = &dys,
                                         .layout = layout};
        return vkCreateGraphicsPipelines(dev, VK_NULL_HANDLE, 1, &gci, nullptr, p);
    });
    (void)g;
}

} // namespace pl::exec
