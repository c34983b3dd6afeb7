// Include expansion done by the host: BOM/CRLF stripping, #include resolution (own folder, then
// include_dirs), #line directives so errors map back to real files, and cycle detection
// (glslang on its own never returns on a recursive include).
#include "shader/include.hpp"
#include "util/files.hpp"
#include "util/paths.hpp"
#include "util/scan.hpp"

#include <set>
#include <sstream>

namespace fs = std::filesystem;

namespace pl::shader {

std::string display_path(const fs::path& p) {
    std::error_code ec;
    fs::path rel = fs::proximate(p, ec);
    return ec ? p.string() : rel.string();
}

std::string line_name(const std::string& name) {
    std::string out = name;
    for (char& c : out)
        if (static_cast<unsigned char>(c) < 0x20 || c == '"' || c == '\\') c = '?';
    return out;
}

Result<std::string> read_text(const fs::path& file) {
    auto read = read_file_capped(file, max_text_bytes, "shader");
    if (!read) return read.error();
    std::string& s = *read;
    if (s.rfind("\xEF\xBB\xBF", 0) == 0) s.erase(0, 3);  // editors on Windows add a BOM
    std::string out;
    out.reserve(s.size());
    for (size_t i = 0; i < s.size(); ++i)
        if (!(s[i] == '\r' && i + 1 < s.size() && s[i + 1] == '\n')) out += s[i];
    return out;
}

namespace {

// Deeper nesting is a mistake (or a generated chain), not a shader library; without a limit a
// chain of thousands of files exhausted the stack.
constexpr size_t max_include_depth = 64;

struct Expander {
    const std::vector<fs::path>& dirs;
    std::vector<fs::path>& files;
    std::vector<fs::path> canonical_dirs;
    std::set<fs::path> once;
    std::vector<std::pair<fs::path, int>> chain;  // file and #include line leading to the next
    std::set<fs::path> open;                      // the files of `chain`, for the cycle check

    // `first_line` is the file line number of text's first line (the main file's body starts
    // after its #version line). Each file costs O(lines + includes * dirs), so a chain of n
    // files costs O(n), not O(n^2) as when every include re-canonicalised the whole chain.
    Status expand(const fs::path& file, const std::string& text, std::string& out, const std::string& shown,
                  int first_line = 1) {
        const fs::path self = canonical_or_normal(file);
        const fs::path self_dir = canonical_or_normal(file.parent_path());
        std::istringstream in(text);
        std::string line;
        int n = first_line - 1;
        while (std::getline(in, line)) {
            ++n;
            if (scan::is_pragma_once(line)) {
                once.insert(self);
                out += "\n";
                continue;
            }
            auto name_found = scan::include_name(line);
            if (!name_found) {
                out += line;
                out += '\n';
                continue;
            }
            const std::string& name = *name_found;
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
            for (size_t k = 0; k < dirs.size(); ++k)
                if (canonical_dirs[k] != self_dir) tried.push_back(dirs[k] / name);
            std::error_code ec;
            for (const auto& t : tried)
                if (fs::is_regular_file(t, ec)) {
                    found = canonical_or_normal(t);
                    break;
                }
            if (found.empty()) {
                Error e = make_error("cannot find include \"" + name + "\"", {shown, n, col});
                for (const auto& t : tried) {
                    // A name the file system refuses (a link loop, a name too long) says why.
                    std::error_code why;
                    (void)fs::status(t, why);
                    if (why && why != std::errc::no_such_file_or_directory)
                        e.notes.push_back(display_path(t) + ": " + why.message());
                    else
                        e.notes.push_back("looked in " + display_path(t.parent_path()));
                }
                return e;
            }
            if (found == self && chain.empty()) return make_error("\"" + name + "\" includes itself", {shown, n, col});
            if (open.count(found) || found == self) {
                Error e = make_error("include cycle: \"" + name + "\" is already being included", {shown, n, col});
                for (size_t j = 0; j < chain.size(); ++j) {
                    fs::path next = j + 1 < chain.size() ? chain[j + 1].first : file;
                    e.notes.push_back(display_path(chain[j].first) + ":" + std::to_string(chain[j].second) +
                                      " includes " + display_path(next));
                }
                e.notes.push_back(shown + ":" + std::to_string(n) + " includes " + display_path(found));
                return e;
            }
            if (once.count(found)) {
                out += "\n";
                continue;
            }
            if (chain.size() + 1 >= max_include_depth) {
                Error e = make_error("includes nested more than " + std::to_string(max_include_depth) +
                                         " deep: \"" + name + "\" is not expanded", {shown, n, col});
                e.hint = "a chain this long is almost certainly generated or a mistake; flatten it";
                for (size_t j = 0; j < chain.size() && j < 3; ++j)
                    e.notes.push_back(display_path(chain[j].first) + ":" + std::to_string(chain[j].second) + " includes ...");
                return e;
            }
            auto body = read_text(found);
            if (!body) {
                Error e = body.error();
                e.loc = {shown, n, col};
                e.source_line = line;
                return e;
            }
            files.push_back(found);
            std::string inc_shown = line_name(display_path(found));
            out += "#line 1 \"" + inc_shown + "\"\n";
            chain.push_back({self, n});
            open.insert(self);
            auto s = expand(found, *body, out, inc_shown);
            open.erase(self);
            chain.pop_back();
            if (!s) return s;
            out += "#line " + std::to_string(n + 1) + " \"" + line_name(shown) + "\"\n";
        }
        return ok_status();
    }
};

// glslang for Vulkan takes desktop GLSL 140+ and ES 310+, and reports an older #version with no
// line ("#version: ES shaders for SPIR-V require version 310 or higher"); the host knows where
// the line is, so it says so there. WebGL / Shadertoy code is GLSL ES 3.00.
Status check_version(const std::string& line, const std::string& shown, int line_no) {
    std::string_view rest;
    (void)scan::directive(line, &rest);
    size_t p = scan::skip_blanks(rest);
    size_t q = p;
    while (q < rest.size() && rest[q] >= '0' && rest[q] <= '9') ++q;
    auto number = scan::parse_decimal(rest.substr(p, q - p), 100000);
    size_t r = scan::skip_blanks(rest, q);
    size_t t = r;
    while (t < rest.size() && scan::is_word_char(rest[t])) ++t;
    std::string profile(rest.substr(r, t - r));
    bool es = profile == "es";
    bool ok = number && (es ? *number >= 310 : *number >= 140) && (profile.empty() || es || profile == "core");
    if (ok) return ok_status();
    Error e = make_error("'" + line.substr(scan::skip_blanks(line)) + "': passlab compiles Vulkan GLSL, which needs " +
                             (es ? "GLSL ES 310 or higher" : "GLSL 140 or higher") + " (write #version 450)",
                         {shown, line_no, static_cast<int>(scan::skip_blanks(line)) + 1});
    e.hint = es ? "WebGL / Shadertoy code (GLSL ES 3.00) needs porting: #version 450, explicit layout(location) "
                  "outputs, and the frame block instead of iTime/iResolution"
                : "GLSL 1.10-1.30 (gl_FragColor, attribute/varying) needs porting to #version 450";
    return e;
}

} // namespace

Result<Expanded> expand_source(const fs::path& file, const std::string& text, const std::string& shown,
                               const std::string& injected, const std::vector<fs::path>& include_dirs) {
    Expanded ex;
    if (!file.empty()) ex.files.push_back(canonical_or_normal(file));
    // #version stays first; the injected text follows, then #line resynchronises numbering.
    std::istringstream in(text);
    std::string line;
    int version_line = 0;
    std::vector<std::string> lines;
    while (std::getline(in, line)) lines.push_back(line);
    for (size_t i = 0; i < lines.size(); ++i) {
        if (scan::is_version(lines[i])) {
            version_line = static_cast<int>(i) + 1;
            break;
        }
        // Only comments and blank lines may precede #version.
        size_t p = scan::skip_blanks(lines[i]);
        if (p < lines[i].size() && lines[i].compare(p, 2, "//") != 0) break;
    }
    if (version_line)
        if (auto s = check_version(lines[static_cast<size_t>(version_line - 1)], shown, version_line); !s) return s.error();
    std::string body;
    for (size_t i = static_cast<size_t>(version_line); i < lines.size(); ++i) {
        body += lines[i];
        body += '\n';
    }
    ex.text = version_line ? lines[static_cast<size_t>(version_line - 1)] + "\n" : "#version 450\n";
    ex.text += "#extension GL_GOOGLE_cpp_style_line_directive : require\n";
    ex.text += "#line 1 \"<passlab preamble>\"\n";
    ex.text += injected;
    ex.text += "#line " + std::to_string(version_line + 1) + " \"" + line_name(shown) + "\"\n";
    Expander e{include_dirs, ex.files, {}, {}, {}, {}};
    for (const auto& d : include_dirs) e.canonical_dirs.push_back(canonical_or_normal(d));
    // Lines before #version (comments) are dropped: they cannot hold code.
    std::error_code ec;
    const fs::path where = file.empty() ? fs::current_path(ec) / shown : file;
    if (auto s = e.expand(where, body, ex.text, shown, version_line + 1); !s)
        return s.error();
    return ex;
}

} // namespace pl::shader
