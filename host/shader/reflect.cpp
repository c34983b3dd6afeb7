// A small SPIR-V reflector: enough of the module's types, names and decorations to bind
// resources by name, size push constants, read the compute local size and measure private memory.
#include "shader/program.hpp"
#include "shader/spirv_words.hpp"

#include <algorithm>
#include <array>
#include <map>
#include <optional>

namespace pl::shader {

namespace {

// Opcodes and enums from the SPIR-V 1.6 specification.
enum : uint32_t {
    OpName = 5, OpMemberName = 6, OpExecutionMode = 16, OpTypeVoid = 19, OpTypeBool = 20, OpTypeInt = 21,
    OpTypeFloat = 22, OpTypeVector = 23, OpTypeMatrix = 24, OpTypeImage = 25, OpTypeSampler = 26,
    OpTypeSampledImage = 27, OpTypeArray = 28, OpTypeRuntimeArray = 29, OpTypeStruct = 30, OpTypePointer = 32,
    OpConstant = 43, OpSpecConstant = 50, OpVariable = 59, OpDecorate = 71, OpMemberDecorate = 72,
    OpExecutionModeId = 331,
};
enum : uint32_t { DecBlock = 2, DecBufferBlock = 3, DecBuiltIn = 11, DecNonWritable = 24, DecNonReadable = 25,
                  DecLocation = 30, DecBinding = 33, DecDescriptorSet = 34, DecOffset = 35 };
enum : uint32_t { SCUniformConstant = 0, SCInput = 1, SCUniform = 2, SCOutput = 3, SCWorkgroup = 4, SCPrivate = 6,
                  SCFunction = 7, SCPushConstant = 9, SCStorageBuffer = 12 };
enum : uint32_t { ModeLocalSize = 17, ModeLocalSizeId = 38 };

struct Type {
    uint32_t op = 0;
    std::vector<uint32_t> args;  // operands after the result id
};

struct Module {
    std::map<uint32_t, Type> types;
    std::map<uint32_t, uint64_t> constants;
    std::map<uint32_t, std::string> names;
    std::map<std::pair<uint32_t, uint32_t>, uint32_t> member_offsets;
    std::map<uint32_t, std::map<uint32_t, uint32_t>> decorations;  // id -> decoration -> value
    std::map<uint32_t, bool> member_non_writable;  // struct id -> any member NonWritable
    struct Var { uint32_t id, type, storage; };
    std::vector<Var> vars;
    uint32_t local_size[3] = {1, 1, 1};
    std::optional<std::array<uint32_t, 3>> local_size_ids;
};


// The fewest words (opcode word included) an instruction this reader looks into must have for
// every operand it reads to exist; 0 for the instructions it skips. The specification's own
// minimum for each, except where a shorter form is legal and handled (OpDecorate without a value).
uint32_t min_words(uint32_t op) {
    switch (op) {
    case OpName: return 2;
    case OpExecutionMode: case OpExecutionModeId: return 3;
    case OpDecorate: return 3;
    case OpMemberDecorate: return 4;
    case OpConstant: case OpSpecConstant: case OpVariable: return 4;
    case OpTypeVoid: case OpTypeBool: case OpTypeSampler: case OpTypeStruct: return 2;
    case OpTypeFloat: case OpTypeSampledImage: case OpTypeRuntimeArray: return 3;
    case OpTypeInt: case OpTypeVector: case OpTypeMatrix: case OpTypeArray: case OpTypePointer: return 4;
    case OpTypeImage: return 9;
    default: return op > OpTypeVoid && op < OpTypePointer ? 2 : 0;  // OpTypeOpaque: only its result id is read
    }
}

Result<Module> parse(const std::vector<uint32_t>& w) {
    if (w.size() < 5 || w[0] != 0x07230203u) return make_error("not a SPIR-V module");
    Module m;
    for (size_t i = 5; i < w.size();) {
        uint32_t op = w[i] & 0xffff, len = w[i] >> 16;
        // The words come from glslang or from the SPIR-V cache on disk; a cache file damaged in
        // any way must be refused here, not read past its end.
        if (len == 0 || i + len > w.size() || len < min_words(op)) return make_error("malformed SPIR-V module");
        const bool local_size = (op == OpExecutionMode && w[i + 2] == ModeLocalSize) ||
                                (op == OpExecutionModeId && w[i + 2] == ModeLocalSizeId);
        if ((local_size && len < 6) || (op == OpMemberDecorate && w[i + 3] == DecOffset && len < 5))
            return make_error("malformed SPIR-V module");
        auto a = [&](size_t k) { return w[i + k]; };
        switch (op) {
        case OpName: m.names[a(1)] = spirv_string(w, i + 2, i + len); break;
        case OpExecutionMode:
            if (a(2) == ModeLocalSize) m.local_size[0] = a(3), m.local_size[1] = a(4), m.local_size[2] = a(5);
            break;
        case OpExecutionModeId:
            if (a(2) == ModeLocalSizeId) m.local_size_ids = std::array<uint32_t, 3>{a(3), a(4), a(5)};
            break;
        case OpDecorate: m.decorations[a(1)][a(2)] = len > 3 ? a(3) : 1; break;
        case OpMemberDecorate:
            if (a(3) == DecOffset) m.member_offsets[{a(1), a(2)}] = a(4);
            if (a(3) == DecNonWritable) m.member_non_writable[a(1)] = true;
            break;
        case OpConstant:
        case OpSpecConstant: {
            uint64_t v = a(3);
            if (len > 4) v |= static_cast<uint64_t>(a(4)) << 32;
            m.constants[a(2)] = v;
            break;
        }
        case OpVariable: m.vars.push_back({a(2), a(1), a(3)}); break;
        default:
            if (op >= OpTypeVoid && op <= OpTypePointer) {
                Type t;
                t.op = op;
                for (size_t k = 2; k < len; ++k) t.args.push_back(a(k));
                m.types[a(1)] = t;
            }
        }
        i += len;
    }
    if (m.local_size_ids)
        for (int k = 0; k < 3; ++k) m.local_size[k] = static_cast<uint32_t>(m.constants[(*m.local_size_ids)[static_cast<size_t>(k)]]);
    return m;
}

// Byte size of a type (std140/std430 offsets from the module; arrays multiply out).
uint64_t size_of(const Module& m, uint32_t id, int depth = 0) {
    if (depth > 64) return 0;
    auto it = m.types.find(id);
    if (it == m.types.end()) return 0;
    const Type& t = it->second;
    switch (t.op) {
    case OpTypeBool: return 4;
    case OpTypeInt:
    case OpTypeFloat: return t.args[0] / 8;
    case OpTypeVector:
    case OpTypeMatrix: return t.args[1] * size_of(m, t.args[0], depth + 1);
    case OpTypeArray: {
        auto c = m.constants.find(t.args[1]);
        uint64_t n = c == m.constants.end() ? 1 : c->second;
        uint64_t e = size_of(m, t.args[0], depth + 1);
        auto stride = m.decorations.find(id);
        (void)stride;
        // Saturate instead of overflowing: the result is compared with a limit.
        return e && n > UINT64_MAX / e ? UINT64_MAX : n * e;
    }
    case OpTypeRuntimeArray: return 0;
    case OpTypeStruct: {
        uint64_t end = 0, sum = 0;
        for (uint32_t k = 0; k < t.args.size(); ++k) {
            uint64_t s = size_of(m, t.args[k], depth + 1);
            auto off = m.member_offsets.find({id, k});
            if (off != m.member_offsets.end()) end = std::max(end, off->second + s);
            sum = sum + s < sum ? UINT64_MAX : sum + s;
        }
        return end ? end : sum;
    }
    default: return 0;
    }
}

const Type* type(const Module& m, uint32_t id) {
    auto it = m.types.find(id);
    return it == m.types.end() ? nullptr : &it->second;
}

const char* format_name(uint32_t f) {
    // SPIR-V ImageFormat enum -> GLSL layout qualifier.
    switch (f) {
    case 1: return "rgba32f"; case 2: return "rgba16f"; case 3: return "r32f"; case 4: return "rgba8";
    case 5: return "rgba8_snorm"; case 6: return "rg32f"; case 7: return "rg16f"; case 8: return "r11f_g11f_b10f";
    case 9: return "r16f"; case 10: return "rgba16"; case 11: return "rgb10_a2"; case 12: return "rg16";
    case 13: return "rg8"; case 14: return "r16"; case 15: return "r8"; case 21: return "rgba32i";
    case 22: return "rgba16i"; case 23: return "rgba8i"; case 24: return "r32i"; case 30: return "rgba32ui";
    case 31: return "rgba16ui"; case 32: return "rgba8ui"; case 33: return "r32ui"; case 35: return "rg32ui";
    default: return "";
    }
}

} // namespace

namespace {

// Bytes of every variable in one of `classes`, saturating at UINT64_MAX.
uint64_t memory_bytes(const std::vector<uint32_t>& words, std::initializer_list<uint32_t> classes) {
    auto m = parse(words);
    if (!m) return 0;
    uint64_t total = 0;
    for (const auto& v : m->vars) {
        if (std::find(classes.begin(), classes.end(), v.storage) == classes.end()) continue;
        const Type* p = type(*m, v.type);
        if (!p || p->op != OpTypePointer) continue;
        uint64_t s = size_of(*m, p->args[1]);
        total = total + s < total ? UINT64_MAX : total + s;
    }
    return total;
}

} // namespace

uint64_t private_memory_bytes(const std::vector<uint32_t>& words) { return memory_bytes(words, {SCPrivate, SCFunction}); }

uint64_t workgroup_memory_bytes(const std::vector<uint32_t>& words) { return memory_bytes(words, {SCWorkgroup}); }

Result<Reflection> reflect_spirv(const std::vector<uint32_t>& words, Stage stage) {
    auto parsed = parse(words);
    if (!parsed) return parsed.error();
    const Module& m = *parsed;
    Reflection r;
    uint32_t bit = 1u << static_cast<int>(stage);
    for (int k = 0; k < 3; ++k) r.local_size[k] = m.local_size[k];
    for (const auto& v : m.vars) {
        const Type* ptr = type(m, v.type);
        if (!ptr || ptr->op != OpTypePointer) continue;
        uint32_t pointee = ptr->args[1];
        auto dec = m.decorations.find(v.id);
        auto has = [&](uint32_t d) { return dec != m.decorations.end() && dec->second.count(d); };
        auto get = [&](uint32_t d) { return dec->second.at(d); };
        if (v.storage == SCInput && stage == Stage::vertex && has(DecLocation) && !has(DecBuiltIn))
            r.vertex_input_locations.push_back(get(DecLocation));
        if (v.storage == SCOutput && stage == Stage::fragment && has(DecLocation))
            r.fragment_output_count = std::max(r.fragment_output_count, get(DecLocation) + 1);
        if (v.storage == SCPushConstant) {
            r.push_constant_size = static_cast<uint32_t>(size_of(m, pointee));
            r.push_constant_stages = bit;
            continue;
        }
        if (v.storage != SCUniformConstant && v.storage != SCUniform && v.storage != SCStorageBuffer) continue;
        if (!has(DecBinding)) continue;
        Binding b;
        b.set = has(DecDescriptorSet) ? get(DecDescriptorSet) : 0;
        b.binding = get(DecBinding);
        b.stages = bit;
        uint32_t tid = pointee;
        const Type* t = type(m, tid);
        if (t && t->op == OpTypeArray) {
            auto c = m.constants.find(t->args[1]);
            b.count = c == m.constants.end() ? 1 : static_cast<uint32_t>(c->second);
            tid = t->args[0];
            t = type(m, tid);
        } else if (t && t->op == OpTypeRuntimeArray) {
            b.count = 0;
            tid = t->args[0];
            t = type(m, tid);
        }
        if (!t) continue;
        std::string var_name = m.names.count(v.id) ? m.names.at(v.id) : "";
        auto tdec = m.decorations.find(tid);
        bool buffer_block = tdec != m.decorations.end() && tdec->second.count(DecBufferBlock);
        if (t->op == OpTypeStruct) {
            b.block_name = m.names.count(tid) ? m.names.at(tid) : "";
            b.name = var_name.empty() ? b.block_name : var_name;
            b.type = (v.storage == SCStorageBuffer || buffer_block) ? BindingType::storage_buffer
                                                                     : BindingType::uniform_buffer;
            b.block_size = static_cast<uint32_t>(std::min<uint64_t>(size_of(m, tid), UINT32_MAX));
            b.non_writable = has(DecNonWritable) || (m.member_non_writable.count(tid) > 0);
            b.non_readable = has(DecNonReadable);
        } else {
            b.name = var_name;
            const Type* img = t;
            if (t->op == OpTypeSampledImage) {
                b.type = BindingType::combined_image_sampler;
                img = type(m, t->args[0]);
            } else if (t->op == OpTypeSampler) {
                b.type = BindingType::sampler;
                img = nullptr;
            } else if (t->op == OpTypeImage) {
                b.type = t->args[5] == 2 ? BindingType::storage_image : BindingType::sampled_image;
            }
            if (img && img->op == OpTypeImage) {
                // OpTypeImage: sampled type, Dim, Depth, Arrayed, MS, Sampled, Format
                switch (img->args[1]) {
                case 0: b.dim = ImageDim::d1; break;
                case 1: b.dim = ImageDim::d2; break;
                case 2: b.dim = ImageDim::d3; break;
                case 3: b.dim = ImageDim::cube; break;
                case 5: b.dim = ImageDim::buffer; break;
                default: b.dim = ImageDim::none;
                }
                b.shadow = img->args[2] == 1;
                b.arrayed = img->args[3] == 1;
                b.multisampled = img->args[4] == 1;
                const Type* st = type(m, img->args[0]);
                b.is_integer = st && st->op == OpTypeInt;
                b.storage_format = format_name(img->args[6]);
            }
            b.non_writable = has(DecNonWritable);
            b.non_readable = has(DecNonReadable);
        }
        r.bindings.push_back(b);
    }
    return r;
}

} // namespace pl::shader
