#include "exec/params.hpp"

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <sstream>

namespace pl::exec {

using graph::ParamDesc;
using graph::ParamType;

namespace {

// std140 base alignment and size of each param type.
void align_size(ParamType t, uint32_t& align, uint32_t& size) {
    switch (t) {
    case ParamType::f32:
    case ParamType::i32:
    case ParamType::boolean:
    case ParamType::enumeration: align = 4; size = 4; return;
    case ParamType::vec2: align = 8; size = 8; return;
    case ParamType::vec3:
    case ParamType::color3: align = 16; size = 12; return;
    case ParamType::vec4:
    case ParamType::color4: align = 16; size = 16; return;
    }
}

const char* glsl_type(ParamType t) {
    switch (t) {
    case ParamType::f32: return "float";
    case ParamType::i32:
    case ParamType::enumeration: return "int";
    case ParamType::boolean: return "bool";
    case ParamType::vec2: return "vec2";
    case ParamType::vec3:
    case ParamType::color3: return "vec3";
    case ParamType::vec4:
    case ParamType::color4: return "vec4";
    }
    return "float";
}

std::string upper_identifier(const std::string& s) {
    std::string out;
    for (char c : s) out += std::isalnum(static_cast<unsigned char>(c)) ? static_cast<char>(std::toupper(c)) : '_';
    return out;
}

bool is_int_type(ParamType t) {
    return t == ParamType::i32 || t == ParamType::boolean || t == ParamType::enumeration;
}

} // namespace

ParamLayout layout_params(const std::vector<ParamDesc>& params) {
    ParamLayout L;
    uint32_t off = 0;
    for (const auto& p : params) {
        uint32_t align = 4, size = 4;
        align_size(p.type, align, size);
        off = (off + align - 1) / align * align;
        L.slots.push_back({p.name, p.type, off});
        off += size;
    }
    L.size = (off + 15) / 16 * 16;
    return L;
}

std::string params_glsl(const std::vector<ParamDesc>& params) {
    if (params.empty()) return {};
    std::ostringstream s;
    s << "layout(set = 0, binding = 1, std140) uniform PasslabParams {\n";
    for (const auto& p : params) s << "    " << glsl_type(p.type) << " " << p.name << ";\n";
    s << "} params;\n";
    for (const auto& p : params) {
        if (p.type != ParamType::enumeration) continue;
        for (size_t i = 0; i < p.options.size(); ++i)
            s << "#define " << upper_identifier(p.name) << "_" << upper_identifier(p.options[i]) << " "
              << i << "\n";
    }
    return s.str();
}

std::vector<uint8_t> pack_params(const std::vector<ParamDesc>& params, const ParamLayout& layout) {
    std::vector<uint8_t> bytes(std::max<uint32_t>(layout.size, 16), 0);
    for (size_t i = 0; i < params.size() && i < layout.slots.size(); ++i) {
        const auto& p = params[i];
        uint8_t* dst = bytes.data() + layout.slots[i].offset;
        int n = p.components();
        for (int c = 0; c < n; ++c) {
            if (is_int_type(p.type)) {
                int32_t v = static_cast<int32_t>(p.value[static_cast<size_t>(c)]);
                std::memcpy(dst + 4 * c, &v, 4);
            } else {
                float v = static_cast<float>(p.value[static_cast<size_t>(c)]);
                std::memcpy(dst + 4 * c, &v, 4);
            }
        }
    }
    return bytes;
}

Status apply_param_value(std::vector<ParamDesc>& params, const std::string& name,
                         const graph::Value& value, const SourceLoc& loc) {
    auto it = std::find_if(params.begin(), params.end(), [&](const ParamDesc& p) { return p.name == name; });
    if (it == params.end()) {
        std::vector<std::string> names;
        for (const auto& p : params) names.push_back(p.name);
        Error e = make_error("unknown param '" + name + "'", loc);
        e.resource = name;
        suggest(e, name, names, "params", "this preset has no params");
        return e;
    }
    ParamDesc& p = *it;
    auto bad = [&](const std::string& why) {
        Error e = make_error("param '" + name + "': " + why, loc);
        e.resource = name;
        return e;
    };
    std::vector<double> nums;
    if (auto d = std::get_if<double>(&value)) nums = {*d};
    else if (auto b = std::get_if<bool>(&value)) nums = {*b ? 1.0 : 0.0};
    else if (auto v = std::get_if<std::vector<double>>(&value)) nums = *v;
    else if (auto s = std::get_if<std::string>(&value)) {
        if (p.type == ParamType::enumeration) {
            auto o = std::find(p.options.begin(), p.options.end(), *s);
            if (o == p.options.end()) {
                Error e = bad("'" + *s + "' is not one of its options");
                suggest(e, *s, p.options, "options");
                return e;
            }
            nums = {static_cast<double>(o - p.options.begin())};
        } else {
            return bad("expects a number, not '" + *s + "'");
        }
    }
    int n = p.components();
    if (static_cast<int>(nums.size()) != n)
        return bad("expects " + std::to_string(n) + " value(s), got " + std::to_string(nums.size()));
    for (int c = 0; c < n; ++c) {
        double v = nums[static_cast<size_t>(c)];
        // NaN passed every min/max comparison below (all are false with it); inf is no value.
        if (!std::isfinite(v)) return bad("expects a finite number");
        if (p.type == ParamType::i32 && v != std::trunc(v)) return bad("expects an integer");
        if (p.type == ParamType::i32 && std::fabs(v) > 2147483647.0) return bad("is outside the 32-bit integer range");
        auto num = [](double x) {
            char b[32];
            std::snprintf(b, sizeof b, "%g", x);
            return std::string(b);
        };
        if (p.min && v < *p.min) return bad("value " + num(v) + " is below its min " + num(*p.min));
        if (p.max && v > *p.max) return bad("value " + num(v) + " is above its max " + num(*p.max));
        p.value[static_cast<size_t>(c)] = v;
    }
    return ok_status();
}

Status apply_param_override(std::vector<ParamDesc>& params, const std::string& assignment) {
    auto eq = assignment.find('=');
    if (eq == std::string::npos || eq == 0) {
        Error e = make_error("--set expects name=value, got '" + assignment + "'");
        e.code = ExitCode::usage;
        return e;
    }
    std::string name = assignment.substr(0, eq), text = assignment.substr(eq + 1);
    graph::Value value;
    if (text == "true" || text == "false") {
        value = text == "true";
    } else {
        std::vector<double> nums;
        std::stringstream ss(text);
        std::string part;
        bool numeric = !text.empty();
        while (std::getline(ss, part, ',')) {
            try {
                size_t used = 0;
                nums.push_back(std::stod(part, &used));
                while (used < part.size() && std::isspace(static_cast<unsigned char>(part[used]))) ++used;
                if (used != part.size()) numeric = false;
            } catch (...) {
                numeric = false;
            }
        }
        if (numeric && nums.size() == 1) value = nums[0];
        else if (numeric) value = nums;
        else value = text;
    }
    SourceLoc loc{"--set " + assignment, 0, 0};
    return apply_param_value(params, name, value, loc);
}

bool assigns(const std::vector<std::string>& assignments, const std::string& name) {
    for (const auto& a : assignments)
        if (a.size() > name.size() && a.compare(0, name.size(), name) == 0 && a[name.size()] == '=') return true;
    return false;
}

} // namespace pl::exec
