// ISF (Interactive Shader Format, v2): a fragment shader whose first comment is a JSON header
// declaring INPUTS, PASSES and IMPORTED images; the .vs beside it, when present, is its vertex
// stage. isf_header.cpp reads the header, isf_preset.cpp writes the preset.
#pragma once

#include "util/error.hpp"

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pl::import {

struct IsfInput {
    std::string name, type, label;   // type: float bool long color point2D event image audio audioFFT
    std::vector<double> def, min, max;  // DEFAULT, MIN, MAX (1..4 numbers)
    std::vector<int> values;         // long: VALUES
    std::vector<std::string> labels; // long: LABELS
    SourceLoc loc;
};

struct IsfPass {
    std::string target;              // empty: the output
    bool persistent = false, is_float = false;
    std::string width, height;       // expressions, empty = the render size
    SourceLoc loc, width_loc, height_loc;
};

struct IsfDesc {
    std::string description, credit;
    std::vector<std::string> categories;
    std::vector<IsfInput> inputs;
    std::vector<IsfPass> passes;     // at least one (an empty header has one output pass)
    std::vector<std::pair<std::string, std::string>> imported;  // name, PATH
    std::string code;                // the .fs with old GLSL rewritten (line count kept)
};

// Parses the header comment of `text` (the .fs as read); errors at file:line:col.
Result<IsfDesc> read_isf(const std::string& text, const std::string& file);
// An ISF size expression ("$WIDTH/2", "floor($HEIGHT/4)", "max(1, $WIDTH/$scale)") as a passlab
// size expression ("view.w/2" ...); decimal literals and ceil cannot be expressed there.
// `terms` replaces an input's default term (params.NAME), e.g. a long input's VALUE lookup.
Result<std::string> isf_size_expression(const std::string& e, const SourceLoc& loc,
                                        const std::map<std::string, std::string>& terms = {});

} // namespace pl::import
