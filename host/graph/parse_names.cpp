// Names in preset.toml that become GLSL identifiers: params (`params.NAME`), images and buffers
// (bound by the name a shader declares). A name glslang would reject must be refused here, at
// its TOML line, rather than as a confusing shader error in generated code.
#include "graph/parse_parts.hpp"

#include <cctype>
#include <set>

namespace pl::graph {

namespace {

const std::set<std::string>& glsl_reserved() {
    static const std::set<std::string> words = [] {
        std::set<std::string> w = {
            // Keywords (GLSL 4.60, section 3.6).
            "attribute", "const", "uniform", "varying", "buffer", "shared", "layout", "centroid", "flat",
            "smooth", "noperspective", "break", "continue", "do", "for", "while", "switch", "case", "default",
            "if", "else", "in", "out", "inout", "float", "double", "int", "void", "bool", "true", "false",
            "discard", "return", "struct", "uint", "precision", "highp", "mediump", "lowp", "invariant",
            "coherent", "volatile", "restrict", "readonly", "writeonly", "patch", "sample", "subroutine",
            "atomic_uint", "precise", "nonuniformEXT", "demote", "subpassInput", "isubpassInput",
            "usubpassInput", "subpassInputMS", "isubpassInputMS", "usubpassInputMS", "sampler",
            "samplerShadow",
            // Reserved for future use (glslang rejects them as identifiers).
            "common", "partition", "active", "asm", "class", "union", "enum", "typedef", "template", "this",
            "resource", "goto", "inline", "noinline", "public", "static", "extern", "external", "interface",
            "long", "short", "half", "fixed", "unsigned", "superp", "input", "output", "hvec2", "hvec3",
            "hvec4", "fvec2", "fvec3", "fvec4", "filter", "sizeof", "cast", "namespace", "using",
            "sampler3DRect", "image1DShadow", "image2DShadow", "image1DArrayShadow", "image2DArrayShadow",
            // A uniform named `texture` hides the built-in function every shader calls.
            "texture",
            // passlab's own block and entry names.
            "frame", "params", "main"};
        for (const char* base : {"vec", "ivec", "uvec", "bvec", "dvec", "i64vec", "u64vec", "f16vec"})
            for (int n = 2; n <= 4; ++n) w.insert(base + std::to_string(n));
        for (const char* base : {"mat", "dmat", "f16mat"})
            for (int c = 2; c <= 4; ++c) {
                w.insert(base + std::to_string(c));
                for (int r = 2; r <= 4; ++r) w.insert(base + std::to_string(c) + "x" + std::to_string(r));
            }
        for (const char* prefix : {"", "i", "u"})
            for (const char* kind : {"sampler", "image", "texture"})
                for (const char* dim : {"1D", "2D", "3D", "Cube", "2DRect", "1DArray", "2DArray", "CubeArray", "Buffer",
                                        "2DMS", "2DMSArray"}) {
                    std::string t = std::string(prefix) + kind + dim;
                    w.insert(t);
                    if (*prefix == 0 && std::string(kind) == "sampler") w.insert(t + "Shadow");
                }
        return w;
    }();
    return words;
}

} // namespace

bool is_identifier(const std::string& s) {
    if (s.empty() || !(std::isalpha(static_cast<unsigned char>(s[0])) || s[0] == '_')) return false;
    for (char c : s)
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '_')) return false;
    return true;
}

Status check_name(const TableReader& r, const std::string& key, const char* what) {
    // glslang refuses identifiers over 1024 characters, and names also become macros
    // (NAME_OPTION): a generous bound here keeps the error at the key, not in the preamble.
    constexpr size_t kMaxName = 128;
    if (key.size() > kMaxName)
        return r.error(std::string(what) + " name '" + key.substr(0, 32) + "...' is " + std::to_string(key.size()) +
                           " characters long; names are limited to " + std::to_string(kMaxName),
                       r.key_loc(key));
    if (!is_identifier(key))
        return r.error(std::string(what) + " name '" + key + "' must be an identifier (letters, digits, _; not starting with a digit)",
                       r.key_loc(key));
    if (glsl_reserved().count(key))
        return r.error(std::string(what) + " name '" + key + "' is a GLSL keyword or a reserved name; shaders could not use it",
                       r.key_loc(key));
    if (key.rfind("gl_", 0) == 0 || key.find("__") != std::string::npos)
        return r.error(std::string(what) + " name '" + key + "' is reserved by GLSL (names starting with gl_ or containing __)",
                       r.key_loc(key));
    return ok_status();
}

const std::vector<std::string>& compare_ops() {
    static const std::vector<std::string> ops = {"never", "less", "equal", "less_equal", "greater", "not_equal",
                                                 "greater_equal", "always"};
    return ops;
}

} // namespace pl::graph
