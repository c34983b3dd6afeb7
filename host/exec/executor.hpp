// The one generic executor: owns a built graph's GPU resources and pipelines and runs frames.
// Each frame: fill the frame and params blocks, then for every pass in planned order and every
// repeat iteration derive barriers from the pass's uses (planner), write its descriptors by
// name, and record its kind (fullscreen, draw, compute, blit, copy, mips, clear).
#pragma once

#include "exec/build.hpp"
#include "exec/cameras.hpp"
#include "exec/keyboard.hpp"
#include "exec/pipelines.hpp"
#include "exec/resources.hpp"
#include "image/image.hpp"
#include "vk/context.hpp"

#include <glm/glm.hpp>

#include <chrono>
#include <memory>
#include <optional>

namespace pl::exec {

// Order in which the instances of a draw are submitted. `reversed` and `shuffled` draw one
// instance per call with firstInstance = its index, so gl_InstanceIndex is unchanged and only
// the order differs: the basis of the `order_independent` test property.
enum class InstanceOrder { natural, reversed, shuffled };

struct FrameInput {
    double time = 0.0;
    double delta = 1.0 / 60.0;
    int index = 0;
    glm::vec4 mouse{0.0f};
    KeyboardState keys;  // frame.keys
    std::optional<graph::OrbitCamera> camera;  // default: [view].camera
    glm::vec2 jitter{0.0f};                    // sub-pixel offset in pixels
    InstanceOrder instance_order = InstanceOrder::natural;
};

// A buffer's counter word (`counter = { offset, capacity }`) as read after each frame, with the
// largest count this executor saw and the first frame it went above the capacity.
struct CounterReading {
    std::string buffer;
    uint32_t offset = 0;    // bytes
    uint64_t capacity = 0;  // evaluated at the executor's size
    uint32_t count = 0;     // the word after the last frame
    int frame = -1;         // that frame's index (-1: none yet)
    uint32_t peak = 0;      // largest count so far, after frame peak_frame
    int peak_frame = -1;
    uint32_t overflow_count = 0;  // the count after overflow_frame, the first above capacity
    int overflow_frame = -1;      // -1: never overflowed
    bool overflow() const { return frame >= 0 && count > capacity; }
};

// "buffer 'nodes' counted N > capacity M after frame F" (the first overflow), for every verb.
std::string overflow_message(const CounterReading& c);

struct PassTiming {
    std::string name;
    double gpu_ms = 0.0;
};

class Executor {
  public:
    // With a pipeline cache (the live lab's), passes whose pipeline is unchanged share it with
    // the previous executor instead of compiling it again.
    static Result<std::unique_ptr<Executor>> create(vk::Context& ctx, CompiledGraph graph, PipelineCache* cache = nullptr);
    ~Executor();

    // Records, submits and waits for one frame (watchdog: `timeout`).
    Status render(const FrameInput& in);
    // Reads back an image (its current contents, after the last frame) as RGBA float.
    Result<image::Image> read(const std::string& image, int mip = 0, int layer = 0);

    // Reads back a buffer (its contents after the last frame) as 32-bit words.
    Result<std::vector<uint32_t>> read_buffer(const std::string& buffer);
    // Every declared counter, read after each frame (a 4-byte copy each, no full readback).
    const std::vector<CounterReading>& counters() const { return counters_; }

    // Records a blit of `image` (its current contents) into the rectangle `to` of `dst`, which
    // the caller has put in TRANSFER_DST_OPTIMAL; the source's transition comes from the
    // planner. For presenting (the live lab's view sits beside its docked panel).
    Status record_blit_to(VkCommandBuffer cb, const std::string& image, VkImage dst, VkRect2D to);
    // Whether record_blit_to can show `image` (single-sampled colour, a blittable float/unorm
    // format); the live lab checks this when a graph is built, so a bad [output] is a reload error.
    Status check_showable(const std::string& image) const;

    const CompiledGraph& graph() const { return *graph_; }
    // Param values are read every frame, so the live lab's panel edits them here directly.
    std::vector<graph::ParamDesc>& params() { return graph_->desc.params; }
    // The graph's images as created (extent, mips, layers, samples), for inspection.
    const GraphResources& resources() const { return res_; }
    // Passes whose pipeline was created by this executor (the others came from the cache).
    const std::vector<std::string>& rebuilt_passes() const { return rebuilt_; }
    // Takes over the contents of `old`'s images that have the same name and the same shape
    // (format, size, mips, layers, samples, history), and its frame count, so a reload keeps
    // accumulated and history images instead of starting from black. File and generator images
    // are uploaded fresh (their source may be what changed).
    Status adopt_contents(Executor& old);
    const std::vector<PassTiming>& timings() const { return timings_; }
    // The named cameras as the last frame saw them (block order: a cube camera has six entries
    // from cameras_first()[i]), for the panel.
    const std::vector<CameraBlock>& camera_entries() const { return cameras_.entries; }
    const std::vector<int>& cameras_first() const { return cameras_.first; }
    // frame.accum_frame of the last frame: frames since the camera, view size or a param changed.
    int accum_frame() const { return accum_frame_; }
    // Why the cameras are last frame's ones (a param gave one an invalid value); empty if not.
    const std::string& camera_error() const { return camera_error_; }
    // CPU time the last render() spent filling blocks, writing descriptors and recording
    // commands: the host's own cost per frame, before submit and wait.
    double record_ms() const { return record_ms_; }
    void set_timeout(std::chrono::milliseconds t) { timeout_ = t; }
    // Per-pass GPU timestamps cost time on some drivers (lavapipe waits for the work before a
    // timestamp): on by default, off for pure frame-time measurements.
    void set_timestamps(bool on) { timestamps_ = on && queries_; }

  private:
    explicit Executor(vk::Context& ctx) : ctx_(ctx) {}
    std::string timeout_cause() const;  // why a frame may exceed the watchdog
    struct Impl;
    Status record_frame(VkCommandBuffer cb, const FrameInput& in);
    // One run of a pass: its own iteration and, in a [[group]], the group's iteration.
    Status record_pass(VkCommandBuffer cb, size_t pass, int iteration, int group_iteration = 0);
    Status create_counters();                    // buffer_readback.cpp
    void record_counter_reads(VkCommandBuffer cb);  // at the end of a frame
    void collect_counters();                       // after its fence
    // The offset of the frame block a pass iteration sees: pass camera `camera` (an index into
    // [cameras], -1 = the view's; `layer` picks a cube camera's face) and render size `size`.
    // Blocks are written into frame_ubo_ as first needed in the frame, one per distinct pair.
    Result<VkDeviceSize> frame_offset(int camera, int layer, VkExtent2D size);
    Status record_buffer_image_copy(VkCommandBuffer cb, const graph::PassDesc& pd, PhysBuffer* b,
                                    PhysImage* p, const vk::FormatInfo* f, bool to_image);

    vk::Context& ctx_;
    std::unique_ptr<CompiledGraph> graph_;
    GraphResources res_;
    std::vector<std::shared_ptr<PassPipeline>> pipelines_;
    std::vector<std::string> rebuilt_;
    double record_ms_ = 0.0;
    // `bake = true` passes run on this executor's first frame, then only when the params block
    // differs from the one they last ran with.
    bool baked_ = false;
    std::vector<uint8_t> baked_params_;
    bool run_baked_ = true;  // this frame
    vk::Buffer frame_ubo_, params_ubo_, cameras_ubo_;
    // Frame blocks of this frame in frame_ubo_ (slot 0: the view's at the view size).
    struct FrameSlot {
        int entry;  // camera block entry, -1 = the view
        uint32_t w, h;
    };
    std::vector<FrameSlot> frame_slots_;
    uint32_t frame_capacity_ = 1;
    VkDeviceSize frame_stride_ = sizeof(FrameBlock);
    FrameBlock frame_base_{};            // this frame's view block, the template of the others
    CameraEntries cameras_;              // this frame's named cameras
    std::vector<glm::mat4> prev_camera_view_proj_;  // last frame's, per entry
    std::vector<int> pass_camera_;       // per pass: index into desc.cameras, -1 = the view
    // Accumulation reset: what the last frame's picture depended on (params block, orbit
    // camera, view size, named cameras) and how many frames in a row it stayed the same.
    std::vector<uint8_t> accum_key_;
    int accum_frame_ = 0;
    std::string camera_error_;
    vk::UniqueDescriptorPool pool_;
    vk::UniqueCommandPool cmd_pool_;
    VkCommandBuffer cmd_ = VK_NULL_HANDLE;
    vk::UniqueFence fence_;
    vk::UniqueQueryPool queries_;
    bool timestamps_ = false;
    std::vector<PassTiming> timings_;
    std::vector<CounterReading> counters_;
    vk::Buffer counter_readback_;  // host-visible, 4 bytes per counter
    InstanceOrder instance_order_ = InstanceOrder::natural;
    int frame_parity_ = 0;  // which physical image of a history pair is "current"
    int frames_rendered_ = 0;
    // The physical image or buffer of a history pair the last frame wrote (readback, blit).
    size_t last_parity() const { return frames_rendered_ > 0 ? static_cast<size_t>((frames_rendered_ - 1) & 1) : 0; }
    glm::mat4 prev_view_proj_{1.0f};
    std::chrono::milliseconds timeout_{std::chrono::seconds(20)};
};

} // namespace pl::exec
