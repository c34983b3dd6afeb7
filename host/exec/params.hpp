// [params] -> one std140 uniform block `params`, its GLSL declaration, its bytes, and the
// `--set name=value` overrides. Enum params become ints with NAME_OPTION defines.
#pragma once

#include "graph/desc.hpp"

#include <cstdint>
#include <map>
#include <string>
#include <vector>

namespace pl::exec {

struct ParamSlot {
    std::string name;
    graph::ParamType type;
    uint32_t offset;  // std140 byte offset
};

struct ParamLayout {
    std::vector<ParamSlot> slots;
    uint32_t size = 0;  // padded to 16
};

ParamLayout layout_params(const std::vector<graph::ParamDesc>& params);

// GLSL: the block (empty string when there are no params) and enum defines.
std::string params_glsl(const std::vector<graph::ParamDesc>& params);

// Current values, packed per the layout.
std::vector<uint8_t> pack_params(const std::vector<graph::ParamDesc>& params, const ParamLayout& layout);

// Applies "name=value" (value: number, comma-separated vector, true/false, enum option name) to
// `params`. Errors name the param and list valid ones / the valid options.
Status apply_param_override(std::vector<graph::ParamDesc>& params, const std::string& assignment);
// Whether one of the "name=value" assignments (`--set` on the command line) sets `name`: what
// the user pinned there wins over saved values and the wall clock.
bool assigns(const std::vector<std::string>& assignments, const std::string& name);
Status apply_param_value(std::vector<graph::ParamDesc>& params, const std::string& name,
                         const graph::Value& value, const SourceLoc& loc);

} // namespace pl::exec
