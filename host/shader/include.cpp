// Include expansion done by the host: BOM/CRLF stripping, #include resolution (own folder, then
// include_dirs), #line directives so errors map back to real files, and cycle detection
// (glslang on its own never returns on a recursive include).
#include "shader/include.hpp"
#include "util/paths.hpp"

#include <fstream>
#include <regex>
#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace pl::shader {

std::string display_path(const fs::path& p) {
    std::error_code ec;
    fs::path rel = fs::proximate(p, ec);
    return ec ? p.string() : rel.string();
}

Result<std::string> read_text(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) return make_error("cannot read '" + display_path(file) + "'");
    std::stringstream ss;
    ss << in.rdbuf();
    std::string s = ss.str();
    if (s.rfind("\xEF\xBB\xBF", 0) == 0) s.erase(0, 3);  // editors on Windows add a BOM
    std::string out;
    out.reserve(s.size());
    for (size_t i = 0; i < s.size(); ++i)
        if (!(s[i] == '\r' && i + 1 < s.size() && s[i + 1] == '\n')) out += s[i];
    return out;
}

namespace {

struct Expander {
    const std::vector<fs::path>& dirs;
    std::vector<fs::path>& files;
    std::set<fs::path> once;
    std::vector<std::pair<fs::path, int>> chain;  // file and #include line leading to the next

    // `first_line` is the file line number of text's first line (the main file's body starts
    // after its #version line).
    Status expand(const fs::path& file, const std::string& text, std::string& out, const std::string& shown,
                  int first_line = 1) {
        static const std::regex inc(R"(^\s*#\s*include\s*[<"]([^">]+)[">].*$)");
        static const std::regex once_re(R"(^\s*#\s*pragma\s+once\b.*$)");
        std::istringstream in(text);
        std::string line;
        int n = first_line - 1;
        while (std::getline(in, line)) {
            ++n;
            std::smatch m;
            if (std::regex_match(line, once_re)) {
                once.insert(fs::weakly_canonical(file));
                out += "\n";
                continue;
            }
            if (!std::regex_match(line, m, inc)) {
                out += line + "\n";
                continue;
            }
            std::string name = m[1];
            int col = static_cast<int>(line.find('#')) + 1;
            fs::path found;
            std::vector<fs::path> tried;
            // Next to the includer first. But when the includer lies in one of the search dirs,
            // the same relative path in an earlier dir (an exercise overlay before the preset,
            // the preset before passes/) shadows it, as top-level shader files are shadowed.
            const fs::path beside = file.parent_path() / name;
            for (size_t k = 0; k < dirs.size(); ++k) {
                auto rel = path_within(beside, dirs[k]);
                if (!rel) continue;
                for (size_t j = 0; j < k; ++j) tried.push_back(dirs[j] / *rel);
                break;  // the first dir that holds the includer decides
            }
            tried.push_back(beside);
            for (const auto& d : dirs)
                if (fs::weakly_canonical(d) != fs::weakly_canonical(file.parent_path())) tried.push_back(d / name);
            std::error_code ec;
            for (const auto& t : tried)
                if (fs::is_regular_file(t, ec)) {
                    found = fs::weakly_canonical(t);
                    break;
                }
            if (found.empty()) {
                Error e = make_error("cannot find include \"" + name + "\"", {shown, n, col});
                for (const auto& t : tried) e.notes.push_back("looked in " + display_path(t.parent_path()));
                return e;
            }
            for (size_t k = 0; k < chain.size(); ++k) {
                if (chain[k].first == found || found == fs::weakly_canonical(file)) {
                    Error e = make_error("include cycle: \"" + name + "\" is already being included", {shown, n, col});
                    for (size_t j = 0; j < chain.size(); ++j) {
                        fs::path next = j + 1 < chain.size() ? chain[j + 1].first : file;
                        e.notes.push_back(display_path(chain[j].first) + ":" + std::to_string(chain[j].second) +
                                          " includes " + display_path(next));
                    }
                    e.notes.push_back(shown + ":" + std::to_string(n) + " includes " + display_path(found));
                    return e;
                }
            }
            if (found == fs::weakly_canonical(file)) {
                Error e = make_error("\"" + name + "\" includes itself", {shown, n, col});
                return e;
            }
            if (once.count(found)) {
                out += "\n";
                continue;
            }
            auto body = read_text(found);
            if (!body) {
                Error e = body.error();
                e.loc = {shown, n, col};
                e.source_line = read_source_line(file.string(), n);
                return e;
            }
            files.push_back(found);
            std::string inc_shown = display_path(found);
            out += "#line 1 \"" + inc_shown + "\"\n";
            chain.push_back({fs::weakly_canonical(file), n});
            if (auto s = expand(found, *body, out, inc_shown); !s) return s;
            chain.pop_back();
            out += "#line " + std::to_string(n + 1) + " \"" + shown + "\"\n";
        }
        return ok_status();
    }
};

} // namespace

Result<Expanded> expand_source(const fs::path& file, const std::string& text, const std::string& shown,
                               const std::string& injected, const std::vector<fs::path>& include_dirs) {
    Expanded ex;
    if (!file.empty()) ex.files.push_back(fs::weakly_canonical(file));
    // #version stays first; the injected text follows, then #line resynchronises numbering.
    std::istringstream in(text);
    std::string line, head, rest;
    int version_line = 0, n = 0;
    std::string all;
    static const std::regex ver(R"(^\s*#\s*version\b.*$)");
    std::vector<std::string> lines;
    while (std::getline(in, line)) lines.push_back(line);
    for (size_t i = 0; i < lines.size(); ++i) {
        if (std::regex_match(lines[i], ver)) {
            version_line = static_cast<int>(i) + 1;
            break;
        }
        // Only comments and blank lines may precede #version.
        std::string t = lines[i];
        t.erase(0, t.find_first_not_of(" \t"));
        if (!t.empty() && t.rfind("//", 0) != 0) break;
    }
    std::string body;
    for (size_t i = static_cast<size_t>(version_line); i < lines.size(); ++i) body += lines[i] + "\n";
    (void)n;
    ex.text = version_line ? lines[static_cast<size_t>(version_line - 1)] + "\n" : "#version 450\n";
    ex.text += "#extension GL_GOOGLE_cpp_style_line_directive : require\n";
    ex.text += "#line 1 \"<passlab preamble>\"\n";
    ex.text += injected;
    ex.text += "#line " + std::to_string(version_line + 1) + " \"" + shown + "\"\n";
    Expander e{include_dirs, ex.files, {}, {}};
    // Lines before #version (comments) are dropped: they cannot hold code.
    if (auto s = e.expand(file.empty() ? fs::current_path() / shown : file, body, ex.text, shown, version_line + 1); !s)
        return s.error();
    return ex;
}

} // namespace pl::shader
