// The pass graph as plain data: what preset.toml says, with the file:line:col of every value so
// that validation, compilation and execution errors can point back at the user's text.
// Parsing (parse.hpp) fills these structs; validation (validate.hpp) checks names, formats, sizes
// and hazards; the planner (exec/plan.hpp) and executor run them. No Vulkan types here.
#pragma once

#include "util/error.hpp"

#include <array>
#include <cstdint>
#include <filesystem>
#include <map>
#include <optional>
#include <string>
#include <variant>
#include <vector>

namespace pl::graph {

// A size expression: a literal vector ([w,h] or [w,h,d] or a single integer) or a text expression
// over `view`, `view.w`, `view.h`, integer params (`params.name`), + - * / % and parentheses.
// "view" is the 2-vector (w,h); scalars broadcast. Examples: "view", "view/2", "view.w*view.h*4".
struct SizeExpr {
    std::string text;              // empty when literal is used
    std::vector<int64_t> literal;  // 1..3 components
    SourceLoc loc;
    bool empty() const { return text.empty() && literal.empty(); }
};

// A float value of a camera: a number or numbers written in the TOML (`literal`), or a text
// expression over view and params evaluated every frame (graph/sizeexpr.hpp: real arithmetic,
// `params.dir * 10`, `params.dir.y`, sin, cos, ...). 1..4 components.
struct FloatExpr {
    std::string text;             // empty when literal is used
    std::vector<double> literal;
    SourceLoc loc;
    bool empty() const { return text.empty() && literal.empty(); }
};

// A 3-vector of a camera: one expression giving 3 components (`[1, 2, 3]`,
// "params.light_dir * 10"), or three scalar ones (`["5 * cos(params.a)", 3, 0]`).
struct Vec3Expr {
    std::vector<FloatExpr> parts;  // 1 (a 3-vector) or 3 (one scalar each)
    SourceLoc loc;
};

// Where the value of each key of a table was written, so that a check made after parsing (a
// reference to an image, a shader file, a size) points at the offending value rather than at the
// start of the table. The parser records every key it reads; nested keys are dotted
// ("depth.image", "set.gain").
struct KeyLocs {
    std::map<std::string, SourceLoc> map;
    // The value's location, or `fallback` when the key was not written.
    SourceLoc at(const std::string& key, const SourceLoc& fallback) const;
};

enum class ImageKind { tex2d, tex2d_array, tex3d, cube };

struct SamplerDesc {
    std::string filter = "linear";      // linear | nearest (mag and min)
    std::string mip_filter = "linear";  // linear | nearest
    std::array<std::string, 3> address = {"repeat", "repeat", "repeat"};  // repeat|clamp|mirror|border
    std::string border = "transparent_black";  // transparent_black | opaque_black | opaque_white
    float anisotropy = 0.0f;  // 0 = off; else max anisotropy (clamped to the device limit)
    std::string compare;      // "" = off; else less | less_equal | greater | ... (shadow maps)
    float lod_bias = 0.0f;
    float min_lod = 0.0f;
    float max_lod = 1000.0f;
    SourceLoc loc;
};

struct ImageDesc {
    std::string name;
    SourceLoc loc;
    ImageKind kind = ImageKind::tex2d;
    std::string format = "rgba8";  // see vk/formats.hpp for the list of names
    SourceLoc format_loc;
    SizeExpr size;       // default "view"; 3 components for tex3d
    int layers = 1;      // tex2d_array layer count (cube: always 6)
    int mips = 1;        // 0 = full chain ("full" in TOML)
    int samples = 1;     // MSAA sample count
    bool history = false;  // keep last frame's content, readable as <name>_prev
    std::string alias;     // another image's name: same memory, own sampler
    std::string file;      // image file (relative to the preset), PNG/EXR/HDR/JPG
    bool srgb = false;     // file/generator colour is sRGB-encoded
    bool flip_y = false;   // file/generator rows uploaded bottom first (OpenGL's UNPACK_FLIP_Y, Shadertoy's vflip)
    std::string generator;  // checker | uv-grid | value-noise | gradient-noise | constant
    std::map<std::string, std::vector<double>> generator_args;  // e.g. cells=[8], color_a=[...]
    // Cleared at the start of every frame. Doubles, so that integer formats clear exactly (a
    // float holds 0xffffffff as 4294967296); vk/clear_value.hpp picks the union member.
    std::optional<std::array<double, 4>> clear;
    SamplerDesc sampler;
    KeyLocs keys;  // value locations: "alias", "file", "generator", "samples", "mips", ...
};

// A counter word inside a buffer (an atomic append index: OIT nodes, particles): the host reads
// it after every frame (4 bytes copied, no full readback) and reports a count above `capacity`.
struct CounterDesc {
    uint32_t offset = 0;  // bytes, a multiple of 4
    SizeExpr capacity;    // elements the buffer holds; a size expression ("view.w*view.h*4")
    SourceLoc loc;
};

struct BufferDesc {
    std::string name;
    SourceLoc loc;
    SizeExpr size;  // bytes
    int stride = 0;  // informational (element size) for dot/inspection
    std::optional<uint32_t> clear;  // filled with this 32-bit value at the start of every frame
    std::vector<double> data;       // initial contents ...
    std::string data_type = "float";  // ... as float | int | uint 32-bit values
    bool history = false;
    std::optional<CounterDesc> counter;
    // Host-built contents (layout: scene/scene_gpu.hpp): "bvh" (nodes + triangles) or
    // "triangles" over `meshes` of [meshes], in that order; the size comes from the build.
    std::string generator;
    std::vector<std::string> meshes;  // locations under "meshes.0", "meshes.1" ...
    int leaf_size = 4;                // bvh: at most this many triangles per leaf (1..kMaxLeafSize)
    static constexpr int kMaxLeafSize = 15;  // = scene::kMaxLeafSize (asserted in exec/resources.cpp)
    KeyLocs keys;
};

// `simplify = { ... }` on a mesh: QEM edge collapses (scene/simplify.hpp) down to a target, and
// optionally on to a coarser morph target whose positions become vertex inputs 4..6.
struct SimplifyLevelDesc {
    std::optional<double> ratio;     // (0, 1] of the input's triangles
    std::optional<int> triangles;    // >= 1
    std::optional<double> max_error; // >= 0, mesh units
};
struct MeshSimplifyDesc {
    SimplifyLevelDesc target;
    std::optional<SimplifyLevelDesc> morph;
    SourceLoc loc;
};

struct MeshDesc {
    std::string name;
    SourceLoc loc;
    std::string generator;  // plane | cube | sphere | torus | teapot | fullscreen-quad
    std::string file;       // .obj or .gltf/.glb relative to the preset
    std::map<std::string, double> args;  // generator arguments: segments, radius, tube ...
    int instances = 1;
    std::optional<MeshSimplifyDesc> simplify;  // keys "simplify.ratio", "simplify.morph.ratio" ...
    KeyLocs keys;
};

enum class ParamType { f32, i32, boolean, vec2, vec3, vec4, color3, color4, enumeration };

struct ParamDesc {
    std::string name;
    SourceLoc loc;
    ParamType type = ParamType::f32;
    std::array<double, 4> value{};  // enum: index into options; bool: 0/1
    std::optional<double> min, max;
    bool log = false;  // UI slider in log scale
    std::vector<std::string> options;  // enum values; shader sees NAME_OPTION defines
    std::string doc;
    // `clock`: in `run` the value is the local date when the lab started (year, month, day,
    // seconds since midnight; "date": month 0-11 as JavaScript and Shadertoy's iDate count,
    // "date-month1": 1-12 as ISF's DATE); renders and tests keep `value`, so they repeat.
    std::string clock;
    KeyLocs keys;  // "value", "min", "max", ...
    int components() const;  // 1..4
};

// Blend state for one colour target. "off", or a named mode, or full factors.
struct BlendDesc {
    bool enable = false;
    std::string src_color = "one", dst_color = "zero", color_op = "add";
    std::string src_alpha = "one", dst_alpha = "zero", alpha_op = "add";
    std::string write_mask = "rgba";
    SourceLoc loc;
};

struct AttachmentRef {
    std::string image;
    int mip = 0;
    // Layer to render into: >= 0 a fixed layer/face, -1 all layers (layered rendering with
    // gl_Layer), -2 "iteration": the layer equals the repeat index (render each cube face).
    int layer = 0;
    // `mip = "iteration + 1"`, `layer = "iteration / 6"`: expressions evaluated per iteration
    // (exec/views.cpp); when written they replace `mip` / `layer` above.
    SizeExpr mip_expr, layer_expr;
    std::string resolve;  // MSAA: single-sample image to resolve into
    SourceLoc loc;
    SourceLoc resolve_loc;  // where `resolve` is written
};

// A shader binding of one mip level and/or one layer of an image:
// bind = { src = { image = "hiz", mip = "iteration" } }. The shader sees only that level (an
// image view with levelCount 1; its lod 0 is the image's level `mip`) and that layer (a 2D view).
struct ViewRef {
    std::string image;
    SizeExpr mip, layer;  // empty = every level / every layer
    SourceLoc loc;
};

// [[group]]: passes recorded in the listed order `repeat` times, sharing one iteration index;
// `swap` pairs trade places after every group iteration. The planner orders the group as one
// unit with the union of its members' reads and writes.
struct GroupDesc {
    std::string name;
    SourceLoc loc;
    SizeExpr repeat;  // empty = 1
    std::vector<std::string> passes;
    std::vector<std::string> swap;  // pairs, as a pass's swap
    KeyLocs keys;  // "passes", "swap", "repeat"; "passes.N" for the Nth member
};

struct StencilFaceDesc {
    std::string fail = "keep", pass = "keep", depth_fail = "keep";
    std::string compare = "always";
};

struct DepthDesc {
    AttachmentRef target;
    std::string test = "less";  // never|less|equal|less_equal|greater|not_equal|greater_equal|always|off
    bool write = true;
    float bias_constant = 0.0f, bias_slope = 0.0f;  // polygon offset (shadow acne)
    bool clamp = false;
    SourceLoc loc;
};

struct StencilDesc {
    bool enable = false;
    StencilFaceDesc front, back;
    uint32_t reference = 0, read_mask = 0xff, write_mask = 0xff;
    SourceLoc loc;
};

// Per-pass clears; an absent value means "load previous contents".
struct ClearDesc {
    std::optional<std::array<double, 4>> color;  // doubles: exact 32-bit integer clears
    std::optional<float> depth;
    std::optional<uint32_t> stencil;
};

enum class PassKind { fullscreen, draw, compute, blit, mips, clear, copy };
const char* kind_name(PassKind k);  // as written in preset.toml

struct ShaderRef {
    std::string file;  // as written, relative to the preset folder (or passes/)
    SourceLoc loc;
    bool empty() const { return file.empty(); }
};

struct PassDesc {
    std::string name;
    SourceLoc loc;
    PassKind kind = PassKind::fullscreen;

    // Shaders. fullscreen: fragment (vertex optional, host provides one); draw: vertex+fragment
    // (+ geometry, tess_control, tess_eval); compute: compute.
    ShaderRef vertex, fragment, geometry, tess_control, tess_eval, compute;
    std::map<std::string, std::string> defines;  // injected as #define NAME VALUE
    // Renames shader resource names to graph resources for this pass, so one shader in passes/
    // serves many graphs: bind = { blur_in = "hdr" } binds the shader's `blur_in` to image hdr.
    std::map<std::string, std::string> bind;
    SourceLoc bind_loc;
    // Shader names bound to one level/layer (bind = { src = { image, mip, layer } }); their
    // image is also in `bind`.
    std::map<std::string, ViewRef> bind_views;

    // Raster state.
    std::vector<AttachmentRef> targets;  // colour targets in location order
    std::optional<DepthDesc> depth;
    StencilDesc stencil;
    std::vector<BlendDesc> blend;  // one for all targets, or one per target
    ClearDesc clear;
    std::string mesh;              // draw: mesh name; empty = no vertex input
    int vertex_count = 0;          // draw without mesh: vertices from gl_VertexIndex
    std::optional<int> instances;  // overrides the mesh's instance count
    std::string indirect;          // buffer holding VkDrawIndexedIndirectCommand / dispatch args
    uint64_t indirect_offset = 0;
    std::string topology = "triangles";  // triangles|triangle_strip|lines|line_strip|points|patches|triangles_adjacency
    int patch_points = 3;
    std::string cull = "back";     // none|back|front
    std::string front_face = "ccw";
    std::string polygon = "fill";  // fill|line|point
    float line_width = 1.0f;

    // Compute.
    SizeExpr groups;   // work groups
    SizeExpr threads;  // or threads: groups = ceil(threads / local_size)

    // Repetition: run N times with the iteration index in the shader (pl_iteration).
    SizeExpr repeat;  // empty = 1
    // Ping-pong: pairs of image names whose roles swap after every iteration, so iteration i
    // reads what iteration i-1 wrote (blur iterations, Jacobi steps). ["a","b"] = one pair.
    std::vector<std::string> swap;
    SourceLoc swap_loc;

    // blit / copy / mips / clear.
    std::string src, dst;              // blit, copy
    std::string image;                 // mips, clear
    std::string filter = "linear";     // blit filter

    bool enabled = true;
    // `enabled = "params.verify"`: an expression over params (and view) evaluated every frame;
    // the pass runs while it is nonzero, so test-only or optional passes cost nothing when off.
    SizeExpr enabled_when;
    bool bake = false;  // run on an executor's first frame and again only when a param changes
    std::string camera;  // a [cameras] name: the frame block is that camera's; empty = the view's
    KeyLocs keys;  // "mesh", "indirect", "src", "dst", "image", "groups", "kind", ...
};

// A named camera of [cameras]: a light's or a probe's view that a pass renders from
// (`camera = "NAME"`) and that every shader can read (`cameras.NAME`). Evaluated every frame,
// so its values may follow params.
// Entries (cameras, cube faces) the cameras block may hold: 16 KiB, the smallest
// maxUniformBufferRange of any Vulkan device, over 416 bytes per entry (exec/frame_block.hpp
// asserts the size).
inline constexpr int kMaxCameraEntries = 39;

struct CameraDesc {
    std::string name;
    SourceLoc loc;
    bool ortho = false;
    bool cube = false;     // six faces (perspective, 90 degrees, square), standard cube-map orientation
    Vec3Expr eye, target, up;
    FloatExpr fov, near, far, aspect, ortho_height;  // empty: the defaults (45, 0.05, 100, 1, 2)
    KeyLocs keys;  // "eye", "target", "fov", ...
    int faces() const { return cube ? 6 : 1; }
};

struct OrbitCamera {
    std::array<float, 3> target{0, 0, 0};
    float distance = 3.0f;
    float yaw = 30.0f, pitch = 20.0f;  // degrees
};

struct ViewDesc {
    std::array<int, 2> size{640, 360};
    OrbitCamera orbit;
    float fov = 45.0f;  // vertical, degrees
    float near = 0.05f, far = 100.0f;
    bool ortho = false;
    float ortho_height = 2.0f;
    SourceLoc loc;
};

struct PresetMeta {
    std::string title, family, summary;
    std::vector<std::string> tags;
    std::string level;                  // "core" or "extended" (the catalogue's; "" = not said)
    std::vector<std::string> sources;   // citations of the course documents ("000 L893-898")
    std::string invariant;              // what the tests check, in one sentence (docs/catalogue.md)
    std::string author, license, source;  // provenance (imported presets: author, licence, source id)
};

// A generic value of a test case or check argument: number, string, bool or number list.
using Value = std::variant<double, bool, std::string, std::vector<double>>;

struct CheckDesc {
    std::string kind;  // "probe", "no_nan", "range", "mean", ... (see docs/format.md)
    std::map<std::string, Value> args;  // every key but `kind`, checked against the kind's keys
    SourceLoc loc;
    KeyLocs keys;  // where each argument's value is written ("buffer", "mask", "other", ...)
};

struct TestDesc {
    std::string name;
    SourceLoc loc;
    std::optional<std::array<int, 2>> size;
    double time = 0.0;
    int frames = 1;
    double step = 1.0 / 60.0;
    std::vector<int> held_keys;        // `keys`: JavaScript keyCodes held down from the first frame (frame.keys)
    std::array<double, 4> mouse{};     // frame.mouse in every frame (the window's convention: pixels, top-left origin)
    std::map<std::string, Value> set;  // param overrides
    std::optional<OrbitCamera> camera; // overrides [view].camera.orbit
    std::map<std::string, CameraDesc> cameras;  // `cameras = { sun = { eye = ... } }`: replaced cameras
    std::string pass;                  // image to check; empty = output
    int mip = 0, layer = 0;            // which level and layer of it (probes and checks may override)
    std::string golden;                // path relative to preset
    std::map<std::string, double> tolerance;
    std::vector<CheckDesc> checks;     // probes and properties
    std::vector<std::string> requires_features;
    std::string hint;  // shown by `passlab grade` when the case fails (course exercises)
    // Grading (`passlab grade`): the case's points, and who sees its figures. "visible" shows
    // them; "hidden", "after_due_date" and "after_published" (Gradescope's levels) grade the
    // case but keep its figures, images and hint out of what the student sees.
    double weight = 1.0;
    std::string visibility = "visible";
    KeyLocs keys;  // "pass", "size", "set.NAME", ...
};

// What a pass reads and writes, by resource name (known after shader reflection); used by the
// planner and by `passlab graph --dot`.
struct PassIO {
    std::vector<std::string> reads, writes;
};

struct GraphDesc {
    std::filesystem::path file;  // preset.toml (absolute)
    std::filesystem::path dir;   // its folder
    PresetMeta meta;
    ViewDesc view;
    std::vector<ParamDesc> params;
    std::vector<ImageDesc> images;
    std::vector<BufferDesc> buffers;
    std::vector<MeshDesc> meshes;
    std::vector<PassDesc> passes;
    std::vector<GroupDesc> groups;
    std::vector<CameraDesc> cameras;  // [cameras], in the order written
    std::string output;  // image shown / written by render
    SourceLoc output_loc;
    std::vector<TestDesc> tests;

    const ImageDesc* find_image(const std::string& n) const;
    const BufferDesc* find_buffer(const std::string& n) const;
    const MeshDesc* find_mesh(const std::string& n) const;
    const ParamDesc* find_param(const std::string& n) const;
    const PassDesc* find_pass(const std::string& n) const;
    // The group listing pass `n` (nullptr when it runs on its own).
    const GroupDesc* group_of(const std::string& n) const;
    const CameraDesc* find_camera(const std::string& n) const;
};

} // namespace pl::graph
