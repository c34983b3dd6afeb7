// The floor: a minimal hand-written Vulkan program (no passlab code) that renders a fullscreen
// fragment shader into an rgba16f image -- or runs a compute shader writing it as a storage
// image, 8x8 groups -- one submit and fence wait per frame, and prints its frame times.
// tests/bench/compare.sh runs it on the SPIR-V passlab generates for the fBm pass and compares
// with `passlab bench` on the same pass: the host's overhead is the difference.
//
// usage: passlab_floor VERT.spv FRAG.spv WIDTH HEIGHT FRAMES
//        passlab_floor --compute COMP.spv WIDTH HEIGHT FRAMES
#include <vulkan/vulkan.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <vector>

#define CHECK(x)                                                                                   \
    do {                                                                                           \
        VkResult r_ = (x);                                                                         \
        if (r_ != VK_SUCCESS) {                                                                    \
            std::fprintf(stderr, "%s failed: %d\n", #x, r_);                                       \
            std::exit(1);                                                                          \
        }                                                                                          \
    } while (0)

static std::vector<uint32_t> read_spv(const char* path) {
    std::ifstream in(path, std::ios::binary | std::ios::ate);
    if (!in) {
        std::fprintf(stderr, "cannot read %s\n", path);
        std::exit(1);
    }
    size_t n = static_cast<size_t>(in.tellg());
    std::vector<uint32_t> w(n / 4);
    in.seekg(0);
    in.read(reinterpret_cast<char*>(w.data()), static_cast<std::streamsize>(n));
    return w;
}

static uint32_t memory_type(VkPhysicalDevice pd, uint32_t bits, VkMemoryPropertyFlags want) {
    VkPhysicalDeviceMemoryProperties mp;
    vkGetPhysicalDeviceMemoryProperties(pd, &mp);
    for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
        if ((bits & (1u << i)) && (mp.memoryTypes[i].propertyFlags & want) == want) return i;
    for (uint32_t i = 0; i < mp.memoryTypeCount; ++i)
        if (bits & (1u << i)) return i;
    std::exit(1);
}

int main(int argc, char** argv) {
    if (argc != 6) {
        std::fprintf(stderr,
                     "usage: %s VERT.spv FRAG.spv WIDTH HEIGHT FRAMES\n       %s --compute "
                     "COMP.spv WIDTH HEIGHT FRAMES\n",
                     argv[0], argv[0]);
        return 2;
    }
    // Compute: the shader's bindings are frame 0, params 1, the storage image 2 (passlab assigns
    // them in that order; `spirv-dis` on the .spv shows it).
    const bool compute = std::strcmp(argv[1], "--compute") == 0;
    auto vs = compute ? std::vector<uint32_t>() : read_spv(argv[1]), fs = read_spv(argv[2]);
    uint32_t W = static_cast<uint32_t>(std::atoi(argv[3])),
             H = static_cast<uint32_t>(std::atoi(argv[4]));
    int frames = std::atoi(argv[5]);

    VkApplicationInfo app{
        VK_STRUCTURE_TYPE_APPLICATION_INFO, nullptr, "floor", 1, "floor", 1, VK_API_VERSION_1_3};
    VkInstanceCreateInfo ici{
        VK_STRUCTURE_TYPE_INSTANCE_CREATE_INFO, nullptr, 0, &app, 0, nullptr, 0, nullptr};
    VkInstance inst;
    CHECK(vkCreateInstance(&ici, nullptr, &inst));
    uint32_t n = 0;
    vkEnumeratePhysicalDevices(inst, &n, nullptr);
    std::vector<VkPhysicalDevice> pds(n);
    vkEnumeratePhysicalDevices(inst, &n, pds.data());
    VkPhysicalDevice pd = pds.at(0);
    VkPhysicalDeviceProperties props;
    vkGetPhysicalDeviceProperties(pd, &props);

    VkPhysicalDeviceVulkan13Features f13{VK_STRUCTURE_TYPE_PHYSICAL_DEVICE_VULKAN_1_3_FEATURES};
    f13.dynamicRendering = VK_TRUE;
    f13.synchronization2 = VK_TRUE;
    f13.maintenance4 = VK_TRUE;
    float prio = 1.0f;
    VkDeviceQueueCreateInfo qci{
        VK_STRUCTURE_TYPE_DEVICE_QUEUE_CREATE_INFO, nullptr, 0, 0, 1, &prio};
    VkDeviceCreateInfo dci{
        VK_STRUCTURE_TYPE_DEVICE_CREATE_INFO, &f13, 0, 1, &qci, 0, nullptr, 0, nullptr, nullptr};
    VkDevice dev;
    CHECK(vkCreateDevice(pd, &dci, nullptr, &dev));
    VkQueue q;
    vkGetDeviceQueue(dev, 0, 0, &q);

    // Target image.
    VkImageCreateInfo imci{VK_STRUCTURE_TYPE_IMAGE_CREATE_INFO};
    imci.imageType = VK_IMAGE_TYPE_2D;
    imci.format = VK_FORMAT_R16G16B16A16_SFLOAT;
    imci.extent = {W, H, 1};
    imci.mipLevels = imci.arrayLayers = 1;
    imci.samples = VK_SAMPLE_COUNT_1_BIT;
    imci.usage = compute ? VK_IMAGE_USAGE_STORAGE_BIT : VK_IMAGE_USAGE_COLOR_ATTACHMENT_BIT;
    VkImage img;
    CHECK(vkCreateImage(dev, &imci, nullptr, &img));
    VkMemoryRequirements mr;
    vkGetImageMemoryRequirements(dev, img, &mr);
    VkMemoryAllocateInfo mai{
        VK_STRUCTURE_TYPE_MEMORY_ALLOCATE_INFO, nullptr, mr.size,
        memory_type(pd, mr.memoryTypeBits, VK_MEMORY_PROPERTY_DEVICE_LOCAL_BIT)};
    VkDeviceMemory imem;
    CHECK(vkAllocateMemory(dev, &mai, nullptr, &imem));
    CHECK(vkBindImageMemory(dev, img, imem, 0));
    VkImageViewCreateInfo vci{VK_STRUCTURE_TYPE_IMAGE_VIEW_CREATE_INFO};
    vci.image = img;
    vci.viewType = VK_IMAGE_VIEW_TYPE_2D;
    vci.format = imci.format;
    vci.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
    VkImageView view;
    CHECK(vkCreateImageView(dev, &vci, nullptr, &view));

    // Uniform blocks with passlab's layout: frame (528 bytes, binding 0) and params (binding 1)
    // holding octaves, persistence, scale, rotate, speed as the preset's defaults.
    VkBufferCreateInfo bci{VK_STRUCTURE_TYPE_BUFFER_CREATE_INFO, nullptr, 0, 1024,
                           VK_BUFFER_USAGE_UNIFORM_BUFFER_BIT};
    VkBuffer ubo;
    CHECK(vkCreateBuffer(dev, &bci, nullptr, &ubo));
    vkGetBufferMemoryRequirements(dev, ubo, &mr);
    mai.allocationSize = mr.size;
    mai.memoryTypeIndex =
        memory_type(pd, mr.memoryTypeBits,
                    VK_MEMORY_PROPERTY_HOST_VISIBLE_BIT | VK_MEMORY_PROPERTY_HOST_COHERENT_BIT);
    VkDeviceMemory umem;
    CHECK(vkAllocateMemory(dev, &mai, nullptr, &umem));
    CHECK(vkBindBufferMemory(dev, ubo, umem, 0));
    uint8_t* u;
    CHECK(vkMapMemory(dev, umem, 0, VK_WHOLE_SIZE, 0, reinterpret_cast<void**>(&u)));
    std::memset(u, 0, 1024);
    float aspect = float(W) / float(H), res[4] = {float(W), float(H), 1.0f / W, 1.0f / H};
    std::memcpy(u + 464, res, 16);
    std::memcpy(u + 524, &aspect, 4);
    int32_t octaves = 6, rotate = 1;
    float persistence = 0.5f, scale = 4.0f, speed = 0.1f;
    std::memcpy(u + 768 + 0, &octaves, 4);
    std::memcpy(u + 768 + 4, &persistence, 4);
    std::memcpy(u + 768 + 8, &scale, 4);
    std::memcpy(u + 768 + 12, &rotate, 4);
    std::memcpy(u + 768 + 16, &speed, 4);

    const VkShaderStageFlags stages =
        compute ? VK_SHADER_STAGE_COMPUTE_BIT : VK_SHADER_STAGE_ALL_GRAPHICS;
    VkDescriptorSetLayoutBinding b[3] = {{0, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, stages, nullptr},
                                         {1, VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 1, stages, nullptr},
                                         {2, VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1, stages, nullptr}};
    VkDescriptorSetLayoutCreateInfo dslci{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_LAYOUT_CREATE_INFO,
                                          nullptr, 0, compute ? 3u : 2u, b};
    VkDescriptorSetLayout dsl;
    CHECK(vkCreateDescriptorSetLayout(dev, &dslci, nullptr, &dsl));
    VkPushConstantRange pcr{stages, 0, 16};
    VkPipelineLayoutCreateInfo plci{
        VK_STRUCTURE_TYPE_PIPELINE_LAYOUT_CREATE_INFO, nullptr, 0, 1, &dsl, 1, &pcr};
    VkPipelineLayout pl;
    CHECK(vkCreatePipelineLayout(dev, &plci, nullptr, &pl));
    VkDescriptorPoolSize ps[2] = {{VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, 2},
                                  {VK_DESCRIPTOR_TYPE_STORAGE_IMAGE, 1}};
    VkDescriptorPoolCreateInfo dpci{
        VK_STRUCTURE_TYPE_DESCRIPTOR_POOL_CREATE_INFO, nullptr, 0, 1, 2, ps};
    VkDescriptorPool pool;
    CHECK(vkCreateDescriptorPool(dev, &dpci, nullptr, &pool));
    VkDescriptorSetAllocateInfo dsai{VK_STRUCTURE_TYPE_DESCRIPTOR_SET_ALLOCATE_INFO, nullptr, pool,
                                     1, &dsl};
    VkDescriptorSet set;
    CHECK(vkAllocateDescriptorSets(dev, &dsai, &set));
    VkDescriptorBufferInfo bi[2] = {{ubo, 0, 528}, {ubo, 768, 32}};
    VkWriteDescriptorSet w[2] = {{VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, nullptr, set, 0, 0, 1,
                                  VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, nullptr, &bi[0], nullptr},
                                 {VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, nullptr, set, 1, 0, 1,
                                  VK_DESCRIPTOR_TYPE_UNIFORM_BUFFER, nullptr, &bi[1], nullptr}};
    vkUpdateDescriptorSets(dev, 2, w, 0, nullptr);
    if (compute) {
        VkDescriptorImageInfo ii{VK_NULL_HANDLE, view, VK_IMAGE_LAYOUT_GENERAL};
        VkWriteDescriptorSet wi{
            VK_STRUCTURE_TYPE_WRITE_DESCRIPTOR_SET, nullptr, set,     2,      0, 1,
            VK_DESCRIPTOR_TYPE_STORAGE_IMAGE,       &ii,     nullptr, nullptr};
        vkUpdateDescriptorSets(dev, 1, &wi, 0, nullptr);
    }

    VkViewport vp{0, 0, float(W), float(H), 0, 1};
    VkRect2D sc{{0, 0}, {W, H}};
    VkPipeline pipe;
    if (compute) {
        VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO, nullptr, 0,
                                      fs.size() * 4, fs.data()};
        VkShaderModule cm;
        CHECK(vkCreateShaderModule(dev, &smci, nullptr, &cm));
        VkComputePipelineCreateInfo cci{VK_STRUCTURE_TYPE_COMPUTE_PIPELINE_CREATE_INFO};
        cci.stage = {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO,
                     nullptr,
                     0,
                     VK_SHADER_STAGE_COMPUTE_BIT,
                     cm,
                     "main",
                     nullptr};
        cci.layout = pl;
        CHECK(vkCreateComputePipelines(dev, VK_NULL_HANDLE, 1, &cci, nullptr, &pipe));
    } else {
        VkShaderModuleCreateInfo smci{VK_STRUCTURE_TYPE_SHADER_MODULE_CREATE_INFO, nullptr, 0,
                                      vs.size() * 4, vs.data()};
        VkShaderModule vm, fm;
        CHECK(vkCreateShaderModule(dev, &smci, nullptr, &vm));
        smci.codeSize = fs.size() * 4;
        smci.pCode = fs.data();
        CHECK(vkCreateShaderModule(dev, &smci, nullptr, &fm));
        VkPipelineShaderStageCreateInfo st[2] = {
            {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0,
             VK_SHADER_STAGE_VERTEX_BIT, vm, "main", nullptr},
            {VK_STRUCTURE_TYPE_PIPELINE_SHADER_STAGE_CREATE_INFO, nullptr, 0,
             VK_SHADER_STAGE_FRAGMENT_BIT, fm, "main", nullptr}};
        VkPipelineVertexInputStateCreateInfo vi{
            VK_STRUCTURE_TYPE_PIPELINE_VERTEX_INPUT_STATE_CREATE_INFO};
        VkPipelineInputAssemblyStateCreateInfo ia{
            VK_STRUCTURE_TYPE_PIPELINE_INPUT_ASSEMBLY_STATE_CREATE_INFO, nullptr, 0,
            VK_PRIMITIVE_TOPOLOGY_TRIANGLE_LIST};
        VkPipelineViewportStateCreateInfo vps{
            VK_STRUCTURE_TYPE_PIPELINE_VIEWPORT_STATE_CREATE_INFO, nullptr, 0, 1, &vp, 1, &sc};
        VkPipelineRasterizationStateCreateInfo rs{
            VK_STRUCTURE_TYPE_PIPELINE_RASTERIZATION_STATE_CREATE_INFO};
        rs.lineWidth = 1.0f;
        VkPipelineMultisampleStateCreateInfo ms{
            VK_STRUCTURE_TYPE_PIPELINE_MULTISAMPLE_STATE_CREATE_INFO};
        ms.rasterizationSamples = VK_SAMPLE_COUNT_1_BIT;
        VkPipelineColorBlendAttachmentState cba{};
        cba.colorWriteMask = 0xf;
        VkPipelineColorBlendStateCreateInfo cb{
            VK_STRUCTURE_TYPE_PIPELINE_COLOR_BLEND_STATE_CREATE_INFO};
        cb.attachmentCount = 1;
        cb.pAttachments = &cba;
        VkPipelineRenderingCreateInfo rci{VK_STRUCTURE_TYPE_PIPELINE_RENDERING_CREATE_INFO, nullptr,
                                          0, 1, &imci.format};
        VkGraphicsPipelineCreateInfo gci{VK_STRUCTURE_TYPE_GRAPHICS_PIPELINE_CREATE_INFO, &rci};
        gci.stageCount = 2;
        gci.pStages = st;
        gci.pVertexInputState = &vi;
        gci.pInputAssemblyState = &ia;
        gci.pViewportState = &vps;
        gci.pRasterizationState = &rs;
        gci.pMultisampleState = &ms;
        gci.pColorBlendState = &cb;
        gci.layout = pl;
        CHECK(vkCreateGraphicsPipelines(dev, VK_NULL_HANDLE, 1, &gci, nullptr, &pipe));
    }
    VkCommandPoolCreateInfo cpci{VK_STRUCTURE_TYPE_COMMAND_POOL_CREATE_INFO, nullptr,
                                 VK_COMMAND_POOL_CREATE_RESET_COMMAND_BUFFER_BIT, 0};
    VkCommandPool cp;
    CHECK(vkCreateCommandPool(dev, &cpci, nullptr, &cp));
    VkCommandBufferAllocateInfo cbai{VK_STRUCTURE_TYPE_COMMAND_BUFFER_ALLOCATE_INFO, nullptr, cp,
                                     VK_COMMAND_BUFFER_LEVEL_PRIMARY, 1};
    VkCommandBuffer cmd;
    CHECK(vkAllocateCommandBuffers(dev, &cbai, &cmd));
    VkFenceCreateInfo fci{VK_STRUCTURE_TYPE_FENCE_CREATE_INFO};
    VkFence fence;
    CHECK(vkCreateFence(dev, &fci, nullptr, &fence));

    std::vector<double> ms_per_frame;
    for (int f = 0; f < frames; ++f) {
        auto t0 = std::chrono::steady_clock::now();
        float time = f / 60.0f;
        std::memcpy(u + 512, &time, 4);
        VkCommandBufferBeginInfo bbi{VK_STRUCTURE_TYPE_COMMAND_BUFFER_BEGIN_INFO, nullptr,
                                     VK_COMMAND_BUFFER_USAGE_ONE_TIME_SUBMIT_BIT};
        CHECK(vkBeginCommandBuffer(cmd, &bbi));
        VkImageMemoryBarrier2 ib{VK_STRUCTURE_TYPE_IMAGE_MEMORY_BARRIER_2};
        ib.srcStageMask = compute ? VK_PIPELINE_STAGE_2_COMPUTE_SHADER_BIT
                                  : VK_PIPELINE_STAGE_2_COLOR_ATTACHMENT_OUTPUT_BIT;
        ib.dstStageMask = ib.srcStageMask;
        ib.dstAccessMask =
            compute ? VK_ACCESS_2_SHADER_STORAGE_WRITE_BIT : VK_ACCESS_2_COLOR_ATTACHMENT_WRITE_BIT;
        ib.oldLayout = VK_IMAGE_LAYOUT_UNDEFINED;
        ib.newLayout = compute ? VK_IMAGE_LAYOUT_GENERAL : VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
        ib.image = img;
        ib.subresourceRange = {VK_IMAGE_ASPECT_COLOR_BIT, 0, 1, 0, 1};
        VkDependencyInfo di{VK_STRUCTURE_TYPE_DEPENDENCY_INFO};
        di.imageMemoryBarrierCount = 1;
        di.pImageMemoryBarriers = &ib;
        vkCmdPipelineBarrier2(cmd, &di);
        if (compute) {
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pipe);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_COMPUTE, pl, 0, 1, &set, 0,
                                    nullptr);
            vkCmdDispatch(cmd, (W + 7) / 8, (H + 7) / 8, 1);
        } else {
            VkRenderingAttachmentInfo ca{VK_STRUCTURE_TYPE_RENDERING_ATTACHMENT_INFO};
            ca.imageView = view;
            ca.imageLayout = VK_IMAGE_LAYOUT_COLOR_ATTACHMENT_OPTIMAL;
            ca.loadOp = VK_ATTACHMENT_LOAD_OP_DONT_CARE;
            ca.storeOp = VK_ATTACHMENT_STORE_OP_STORE;
            VkRenderingInfo ri{VK_STRUCTURE_TYPE_RENDERING_INFO};
            ri.renderArea = sc;
            ri.layerCount = 1;
            ri.colorAttachmentCount = 1;
            ri.pColorAttachments = &ca;
            vkCmdBeginRendering(cmd, &ri);
            vkCmdBindPipeline(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pipe);
            vkCmdBindDescriptorSets(cmd, VK_PIPELINE_BIND_POINT_GRAPHICS, pl, 0, 1, &set, 0,
                                    nullptr);
            vkCmdDraw(cmd, 3, 1, 0, 0);
            vkCmdEndRendering(cmd);
        }
        CHECK(vkEndCommandBuffer(cmd));
        VkSubmitInfo si{VK_STRUCTURE_TYPE_SUBMIT_INFO, nullptr, 0, nullptr, nullptr, 1, &cmd};
        CHECK(vkQueueSubmit(q, 1, &si, fence));
        CHECK(vkWaitForFences(dev, 1, &fence, VK_TRUE, UINT64_MAX));
        CHECK(vkResetFences(dev, 1, &fence));
        ms_per_frame.push_back(
            std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0)
                .count());
    }
    // The first frames include llvmpipe's shader compilation: drop them like `passlab bench`.
    std::vector<double> measured(
        ms_per_frame.begin() + std::min<size_t>(5, ms_per_frame.size() - 1), ms_per_frame.end());
    std::sort(measured.begin(), measured.end());
    std::printf("floor %s %ux%u on %s: min %.3f ms, median %.3f ms, p95 %.3f ms over %zu frames\n",
                compute ? "compute" : "fragment", W, H, props.deviceName, measured.front(),
                measured[measured.size() / 2],
                measured[std::min(measured.size() - 1, measured.size() * 95 / 100)],
                measured.size());
    vkDeviceWaitIdle(dev);
    vkDestroyDevice(dev, nullptr); // the process ends here; the driver frees the rest
    vkDestroyInstance(inst, nullptr);
    return 0;
}
