#include "import/source_text.hpp"

#include <cctype>
#include <cstdio>
#include <fstream>
#include <sstream>

namespace pl::import {

Result<std::string> read_text_file(const std::filesystem::path& p) {
    std::ifstream in(p, std::ios::binary);
    if (!in) return make_error("cannot read '" + p.string() + "'");
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

std::string clean_text(std::string s) {
    if (s.rfind("\xEF\xBB\xBF", 0) == 0) s.erase(0, 3);
    std::string out;
    out.reserve(s.size());
    for (size_t i = 0; i < s.size(); ++i) {
        if (s[i] == '\r') {
            out += '\n';
            if (i + 1 < s.size() && s[i + 1] == '\n') ++i;
        } else {
            out += s[i];
        }
    }
    return out;
}

namespace {

bool ident_char(char c) { return std::isalnum(static_cast<unsigned char>(c)) || c == '_'; }

// Calls f(begin, end) for every identifier outside comments and preprocessor-free of strings
// (GLSL has none); returns the text with each replaced by f's result.
template <class F> std::string map_words(const std::string& s, F f) {
    std::string out;
    out.reserve(s.size() + 16);
    size_t i = 0;
    while (i < s.size()) {
        if (s.compare(i, 2, "//") == 0) {
            size_t e = s.find('\n', i);
            e = e == std::string::npos ? s.size() : e;
            out.append(s, i, e - i);
            i = e;
        } else if (s.compare(i, 2, "/*") == 0) {
            size_t e = s.find("*/", i + 2);
            e = e == std::string::npos ? s.size() : e + 2;
            out.append(s, i, e - i);
            i = e;
        } else if (ident_char(s[i]) && !std::isdigit(static_cast<unsigned char>(s[i]))) {
            size_t e = i;
            while (e < s.size() && ident_char(s[e])) ++e;
            out += f(s.substr(i, e - i), e);
            i = e;
        } else if (std::isdigit(static_cast<unsigned char>(s[i]))) {
            size_t e = i;
            while (e < s.size() && (ident_char(s[e]) || s[e] == '.')) ++e;  // 1e5, 0x1Fu: not words
            out.append(s, i, e - i);
            i = e;
        } else {
            out += s[i++];
        }
    }
    return out;
}

} // namespace

std::string replace_word(const std::string& s, const std::string& from, const std::string& to) {
    return map_words(s, [&](const std::string& w, size_t) { return w == from ? to : w; });
}

std::string glsl_es_to_450(std::string s) {
    s = clean_text(std::move(s));
    // `#version 300 es` (pasted with the code) would be a second #version: blank it.
    size_t at = 0;
    while (at < s.size()) {
        size_t e = s.find('\n', at);
        if (e == std::string::npos) e = s.size();
        size_t b = s.find_first_not_of(" \t", at);
        if (b < e && s.compare(b, 1, "#") == 0) {
            size_t d = s.find_first_not_of(" \t", b + 1);
            if (d < e && s.compare(d, 7, "version") == 0) s.replace(at, e - at, std::string(e - at, ' '));
        }
        at = e + 1;
    }
    // Names that are types or keywords in Vulkan GLSL 4.50 (GL_KHR_vulkan_glsl, GLSL 4.x) but
    // free identifiers in GLSL ES 3.00.
    static const char* reserved[] = {"sampler", "buffer", "shared", "precise", "texture2D", "texture3D",
                                     "textureCube", "subroutine", "dvec2", "dvec3", "dvec4", "atomic_uint"};
    return map_words(s, [&](const std::string& w, size_t) {
        for (const char* r : reserved)
            if (w == r) return w + "_";
        return w;
    });
}

std::pair<int, int> line_col(const std::string& s, size_t offset) {
    int line = 1, col = 1;
    for (size_t i = 0; i < offset && i < s.size(); ++i) {
        if (s[i] == '\n') ++line, col = 1;
        else ++col;
    }
    return {line, col};
}

std::string toml_quote(const std::string& s) {
    std::string out = "\"";
    for (unsigned char c : s) {
        if (c == '"') out += "\\\"";
        else if (c == '\\') out += "\\\\";
        else if (c == '\n') out += "\\n";
        else if (c == '\t') out += "\\t";
        else if (c < 0x20 || c == 0x7f) {
            char b[8];
            std::snprintf(b, sizeof b, "\\u%04x", c);
            out += b;
        } else out += static_cast<char>(c);
    }
    return out + "\"";
}

} // namespace pl::import
