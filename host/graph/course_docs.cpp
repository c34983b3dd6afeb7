#include "graph/course_docs.hpp"

#include <cctype>

namespace pl::graph {

const std::vector<CourseDoc>& course_docs() {
    // Names from each document's own title page; see docs/references.md for their topics.
    static const std::vector<CourseDoc> docs = {
        {"000", "000_c9f7e5de708ecbb3.txt", "Schmalstieg, Real-Time Rendering (lecture slides)", 6372},
        {"001", "001_fe43b953f362fae7.txt", "Wimmer, Shading and Lighting Effects (TU Wien slides)", 1070},
        {"002", "002_644d46bdce7e5305.txt", "Rosseaux and Ganse, Supraleiter rendering technologies (talk)", 2865},
        {"003", "003_cfc3b5b225ddab3d.txt", "Stanford CS248 (2019), Modern Rendering Techniques (lecture 17)", 970},
        {"004", "004_9a40ad89bdfc582a.txt", "Zachmann, Advanced Shader Programming (Bremen slides)", 1177},
    };
    return docs;
}

const CourseDoc* find_course_doc(const std::string& id) {
    for (const auto& d : course_docs())
        if (id == d.id) return &d;
    return nullptr;
}

namespace {
bool parse_int(const std::string& s, size_t& i, int& out) {
    size_t start = i;
    long long v = 0;
    while (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])) && i - start < 7) v = v * 10 + (s[i++] - '0');
    if (i == start || (i < s.size() && std::isdigit(static_cast<unsigned char>(s[i])))) return false;
    out = static_cast<int>(v);
    return true;
}
} // namespace

Result<Citation> parse_citation(const std::string& text) {
    Citation c;
    const std::string form = "expected a citation like \"000 L893-898\" (document id, then line ranges)";
    size_t sp = text.find(' ');
    std::string id = text.substr(0, sp);
    c.doc = find_course_doc(id);
    if (!c.doc) {
        Error e = make_error("unknown course document '" + id + "' in citation \"" + text + "\"");
        std::vector<std::string> ids;
        for (const auto& d : course_docs()) ids.push_back(d.id);
        suggest(e, id, ids, "documents (docs/references.md)");
        return e;
    }
    if (sp == std::string::npos) return make_error("citation \"" + text + "\" has no line range; " + form);
    size_t i = sp + 1;
    for (;;) {
        if (i >= text.size() || text[i] != 'L') return make_error("citation \"" + text + "\": " + form);
        ++i;
        int a = 0, b = 0;
        if (!parse_int(text, i, a)) return make_error("citation \"" + text + "\": " + form);
        b = a;
        if (i < text.size() && text[i] == '-') {
            ++i;
            if (!parse_int(text, i, b)) return make_error("citation \"" + text + "\": " + form);
        }
        if (a < 1 || b < a)
            return make_error("citation \"" + text + "\": range L" + std::to_string(a) + "-" + std::to_string(b) +
                              " is empty or reversed");
        if (b > c.doc->lines)
            return make_error("citation \"" + text + "\": line " + std::to_string(b) + " is past the end of " +
                              c.doc->file + " (" + std::to_string(c.doc->lines) + " lines)");
        c.ranges.push_back({a, b});
        if (i == text.size()) break;
        if (text.compare(i, 2, ", ") != 0) return make_error("citation \"" + text + "\": " + form);
        i += 2;
    }
    return c;
}

std::string describe(const Citation& c) {
    std::string out = c.doc ? c.doc->name : "?";
    for (size_t k = 0; k < c.ranges.size(); ++k) {
        out += k ? ", L" : " L";
        out += std::to_string(c.ranges[k].first);
        if (c.ranges[k].second != c.ranges[k].first) out += "-" + std::to_string(c.ranges[k].second);
    }
    return out;
}

} // namespace pl::graph
