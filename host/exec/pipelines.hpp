// Pipelines of one pass, built from its description and its shaders' reflection: descriptor
// set layouts and push constants come from SPIR-V, raster state from the graph.
#pragma once

#include "exec/build.hpp"
#include "exec/resources.hpp"
#include "vk/context.hpp"

#include <map>
#include <memory>
#include <string>
#include <vector>

namespace pl::exec {

struct PassPipeline {
    std::vector<vk::UniqueSetLayout> set_layouts;  // index = set number
    vk::UniquePipelineLayout layout;
    vk::UniquePipeline pipeline;
    VkPipelineBindPoint bind_point = VK_PIPELINE_BIND_POINT_GRAPHICS;
    uint32_t push_stages = 0;  // VkShaderStageFlags, 0 = no push constants
};

// Pipelines shared by successive executors of the live lab. The key is everything a pipeline is
// made from (SPIR-V of every stage, binding layout, formats, raster/blend/depth state), byte for
// byte, so a hit is exact. Entries are weak: a pipeline lives while some executor uses it, so a
// reload that changes one pass rebuilds that pass only, and nothing outlives its last user.
class PipelineCache {
  public:
    std::shared_ptr<PassPipeline> find(const std::string& key);
    void insert(const std::string& key, const std::shared_ptr<PassPipeline>& p);

  private:
    std::map<std::string, std::weak_ptr<PassPipeline>> entries_;
};

// An empty PassPipeline (no pipeline) for transfer kinds. Errors (unsupported blend on this
// device, sample count mismatch between targets) name the pass. With a cache, an identical
// pipeline is shared instead of created (`*reused` says which happened).
Result<std::shared_ptr<PassPipeline>> create_pass_pipeline(vk::Context& ctx, const CompiledGraph& g, const CompiledPass& pass,
                                                           const GraphResources& res, PipelineCache* cache = nullptr,
                                                           bool* reused = nullptr);

// Shader stage bits of the reflection (1 << shader::Stage) as Vulkan flags.
VkShaderStageFlags vk_stages(uint32_t stage_bits);
VkPipelineStageFlags2 pipeline_stages(uint32_t stage_bits);
VkDescriptorType descriptor_type(shader::BindingType t);
// An error about a pass, located at its [[pass]] header.
Error pass_error(const graph::PassDesc& pd, const std::string& msg);

} // namespace pl::exec
