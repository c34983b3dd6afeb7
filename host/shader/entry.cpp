#include "shader/entry.hpp"

#include <regex>

namespace pl::shader {

namespace {

// Blanks // and /* */ comments so a commented-out main() does not count (newlines are kept).
std::string without_comments(const std::string& s) {
    std::string out = s;
    for (size_t i = 0; i + 1 < out.size(); ++i) {
        if (out[i] == '/' && out[i + 1] == '/') {
            while (i < out.size() && out[i] != '\n') out[i++] = ' ';
        } else if (out[i] == '/' && out[i + 1] == '*') {
            size_t j = i;
            for (; j + 1 < out.size() && !(out[j] == '*' && out[j + 1] == '/'); ++j)
                if (out[j] != '\n') out[j] = ' ';
            for (size_t k = j; k < std::min(out.size(), j + 2); ++k) out[k] = ' ';
            i = j + 1;
        }
    }
    return out;
}

} // namespace

std::string main_image_entry(const std::string& expanded) {
    static const std::regex main_image(R"(\bvoid\s+mainImage\s*\()");
    static const std::regex main_fn(R"(\bvoid\s+main\s*\(\s*(void\s*)?\))");
    const std::string code = without_comments(expanded);
    if (!std::regex_search(code, main_image) || std::regex_search(code, main_fn)) return {};
    return "#line 1 \"<passlab mainImage entry>\"\n"
           "layout(location = 0) out vec4 pl_main_image_color;\n"
           "void main() {\n"
           "    vec4 c = vec4(0.0);\n"
           "    mainImage(c, gl_FragCoord.xy);\n"
           "    pl_main_image_color = c;\n"
           "}\n";
}

} // namespace pl::shader
