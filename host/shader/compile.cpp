// glslang front end: expanded sources of all stages of a pass are parsed and linked into one
// program, so auto-mapped bindings agree across stages; errors are parsed back into pl::Error
// with the real file and line (from our #line directives) and a column found from the quoted
// token; SPIR-V is reflected and guarded against absurd private memory.
#include "shader/bindings.hpp"
#include "shader/cache.hpp"
#include "shader/culprit.hpp"
#include "shader/entry.hpp"
#include "shader/include.hpp"
#include "shader/program.hpp"
#include "util/scan.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <cctype>
#include <memory>
#include <optional>
#include <set>
#include <mutex>
#include <algorithm>
#include <tuple>
#include <sstream>

namespace fs = std::filesystem;

namespace pl::shader {

const char* stage_name(Stage s) {
    switch (s) {
    case Stage::vertex: return "vertex";
    case Stage::tess_control: return "tess_control";
    case Stage::tess_eval: return "tess_eval";
    case Stage::geometry: return "geometry";
    case Stage::fragment: return "fragment";
    case Stage::compute: return "compute";
    }
    return "?";
}

namespace {

EShLanguage language(Stage s) {
    switch (s) {
    case Stage::vertex: return EShLangVertex;
    case Stage::tess_control: return EShLangTessControl;
    case Stage::tess_eval: return EShLangTessEvaluation;
    case Stage::geometry: return EShLangGeometry;
    case Stage::fragment: return EShLangFragment;
    case Stage::compute: return EShLangCompute;
    }
    return EShLangVertex;
}

void init_glslang() {
    // Once per process, never finalised: glslang's global tables are not reference counted.
    static std::once_flag once;
    std::call_once(once, [] { glslang::InitializeProcess(); });
}

// glslang's name of a stage in link messages ("Linking tessellation control stage: ...").
const char* glslang_stage_name(Stage s) {
    switch (s) {
    case Stage::tess_control: return "tessellation control";
    case Stage::tess_eval: return "tessellation evaluation";
    default: return stage_name(s);
    }
}

struct LogLine {
    std::string file, message;
    int line = 0;
};

// "ERROR: path:line: message". A path may itself hold ":123: " (a folder name, a #line name),
// so the shader names the host gave glslang are tried first, then the first ":digits: ".
std::optional<LogLine> split_log_line(std::string_view s, const std::map<std::string, fs::path>& files) {
    const std::string_view prefix = "ERROR: ";
    if (s.substr(0, prefix.size()) != prefix) return std::nullopt;
    s.remove_prefix(prefix.size());
    auto at = [&](size_t colon) -> std::optional<LogLine> {
        size_t q = colon + 1;
        while (q < s.size() && s[q] >= '0' && s[q] <= '9') ++q;
        if (q == colon + 1 || s.substr(q, 2) != ": ") return std::nullopt;
        auto n = scan::parse_decimal(s.substr(colon + 1, q - colon - 1), 1u << 30);
        return LogLine{std::string(s.substr(0, colon)), std::string(s.substr(q + 2)), n ? static_cast<int>(*n) : 0};
    };
    std::optional<LogLine> best;
    for (const auto& [name, disk] : files)
        if (s.size() > name.size() && s.substr(0, name.size()) == name && s[name.size()] == ':')
            if (auto l = at(name.size()); l && (!best || l->file.size() > best->file.size())) best = l;
    if (best) return best;
    for (size_t p = s.find(':'); p != std::string_view::npos; p = s.find(':', p + 1))
        if (auto l = at(p)) return l;
    return std::nullopt;
}

// The member names of the block or struct variable `instance` declared in `text`
// ("uniform PasslabParams { float scale; int octaves; } params;" -> scale, octaves), or of the
// struct type of a declaration "Light instance;". Empty when it cannot be found.
std::vector<std::string> members_of(const std::string& text, const std::string& instance) {
    auto members_in = [&](size_t open, size_t close) {
        std::vector<std::string> names;
        std::string body = text.substr(open + 1, close - open - 1);
        size_t start = 0;
        for (size_t semi = body.find(';'); semi != std::string::npos; start = semi + 1, semi = body.find(';', start)) {
            std::string decl = body.substr(start, semi - start);
            if (size_t b = decl.find('['); b != std::string::npos) decl.resize(b);  // "float w[4]"
            size_t e = decl.find_last_not_of(" \t\r\n");
            if (e == std::string::npos) continue;
            size_t b = e;
            while (b > 0 && (std::isalnum(static_cast<unsigned char>(decl[b - 1])) || decl[b - 1] == '_')) --b;
            if (b <= e) names.push_back(decl.substr(b, e - b + 1));
        }
        return names;
    };
    auto brace_before = [&](size_t close) -> size_t {
        int depth = 0;
        for (size_t k = close + 1; k-- > 0;) {
            if (text[k] == '}') ++depth;
            else if (text[k] == '{' && --depth == 0) return k;
        }
        return std::string::npos;
    };
    // "} instance;" closes a block or an inline struct declaration.
    auto find_from = [&](size_t from) {
        size_t r = scan::find_word(std::string_view(text).substr(from), instance);
        return r == std::string::npos ? r : r + from;
    };
    for (size_t at = find_from(0); at != std::string::npos; at = find_from(at + instance.size())) {
        size_t k = at;
        while (k > 0 && std::isspace(static_cast<unsigned char>(text[k - 1]))) --k;
        size_t after = at + instance.size();
        while (after < text.size() && std::isspace(static_cast<unsigned char>(text[after]))) ++after;
        if (k > 0 && text[k - 1] == '}' && after < text.size() && (text[after] == ';' || text[after] == '['))
            if (size_t open = brace_before(k - 1); open != std::string::npos) return members_in(open, k - 1);
    }
    return {};
}

// glslang's info log -> Error at path:line:col with the source line. `stage_files` names the
// file of each stage, for link errors ("Linking vertex stage: Missing entry point"), which have
// no line; `fallback_file` is blamed when nothing names one.
//
// `text` is the expanded source glslang saw: a "'x' : no such field in structure 'params'" gets
// the nearest member of that block as "did you mean 'params.y'?" (params, frame, a user's UBO).
Error parse_log(const std::string& log, Stage stage, const std::map<std::string, fs::path>& files,
                const std::string& fallback_file, const std::map<Stage, std::string>& stage_files = {},
                const std::string& text = {}) {
    std::vector<Error> errors;
    std::istringstream in(log);
    std::string line;
    std::vector<std::string> other;
    std::string other_file = fallback_file;
    Stage other_stage = stage;
    while (std::getline(in, line)) {
        if (auto l = split_log_line(line, files)) {
            std::string msg = l->message;
            while (!msg.empty() && msg.back() == ' ') msg.pop_back();
            Error e;
            e.message = std::string(stage_name(stage)) + " shader: " + msg;
            auto f = files.find(l->file);
            std::string disk = f != files.end() ? f->second.string() : l->file;
            e.loc = {l->file, l->line, 0};
            e.source_line = read_source_line(disk, l->line);
            e.loc.col = culprit_column(msg, e.source_line);
            // The token is only where the parser noticed; the mistake is usually just before.
            if (msg.find("syntax error") != std::string::npos && msg.find("expecting COMMA or SEMICOLON") != std::string::npos)
                e.hint = "a ';' is probably missing at the end of the statement before this line";
            if (auto f = msg.find("' : no such field in structure '"); f != std::string::npos && !msg.empty() && msg[0] == '\'') {
                std::string field = msg.substr(1, f - 1);
                size_t s0 = f + std::string("' : no such field in structure '").size();
                std::string instance = msg.substr(s0, msg.find('\'', s0) - s0);
                auto names = members_of(text, instance);
                std::string near = nearest_name(field, names);
                if (!near.empty()) e.hint = "did you mean '" + instance + "." + near + "'?";
                if (!names.empty()) {
                    std::string all;
                    for (const auto& n : names) all += (all.empty() ? "" : ", ") + n;
                    e.notes.push_back(instance + " has: " + all);
                }
            }
            errors.push_back(std::move(e));
        } else if (line.rfind("ERROR: ", 0) == 0 && line.find("compilation errors") == std::string::npos) {
            other.push_back(line.substr(7));
            for (const auto& [st, file] : stage_files)
                if (other.size() == 1 && line.find(std::string("Linking ") + glslang_stage_name(st) + " stage:") != std::string::npos)
                    other_file = file, other_stage = st;
        }
    }
    if (errors.empty()) {
        Error e = make_error(std::string(stage_name(other_stage)) + " shader: " +
                                 (other.empty() ? std::string("glslang failed without a message") : other.front()),
                             {other_file, 0, 0});
        for (size_t i = 1; i < other.size() && i < 10; ++i) e.notes.push_back(other[i]);
        return e;
    }
    Error first = errors.front();
    for (size_t i = 1; i < errors.size() && i < 10; ++i)
        first.notes.push_back(errors[i].loc.str() + ": " + errors[i].message + (errors[i].hint.empty() ? "" : " (" + errors[i].hint + ")"));
    return first;
}

// `first`'s errors (without glslang's "compilation terminated") followed by those of `cascading`
// (the same source parsed on past the first error) at file:line places `first` does not name.
std::string merge_later_errors(const std::string& first, const std::string& cascading) {
    auto place = [](const std::string& line) {  // "ERROR: file:line: " up to the message
        size_t colon = line.find(": '");
        return colon == std::string::npos ? line : line.substr(0, colon);
    };
    std::string out;
    std::set<std::string> seen;
    std::istringstream a(first), b(cascading);
    for (std::string line; std::getline(a, line);) {
        if (line.rfind("ERROR: ", 0) != 0 || line.find("compilation terminated") != std::string::npos ||
            line.find("compilation errors") != std::string::npos)
            continue;
        seen.insert(place(line));
        out += line + "\n";
    }
    for (std::string line; std::getline(b, line);)
        if (line.rfind("ERROR: ", 0) == 0 && line.find("compilation errors") == std::string::npos && seen.insert(place(line)).second)
            out += line + "\n";
    return out;
}

// The line declaring the array with the most elements (`name[12345]`) among `files`; with
// `qualifier`, only lines that hold that word (`shared`).
SourceLoc largest_array_declaration(const std::vector<fs::path>& files, std::string_view qualifier = {}) {
    SourceLoc best;
    unsigned long long most = 0;
    for (const auto& f : files) {
        auto text = read_text(f);
        if (!text) continue;
        std::istringstream in(*text);
        std::string line;
        for (int n = 1; std::getline(in, line); ++n)
            for (size_t open = qualifier.empty() || scan::find_word(line, qualifier) != std::string::npos ? line.find('[') : std::string::npos; open != std::string::npos; open = line.find('[', open + 1)) {
                // identifier, blanks, '[', blanks, digits, blanks, ']'
                size_t e = open;
                while (e > 0 && scan::is_blank(line[e - 1])) --e;
                size_t b = e;
                while (b > 0 && scan::is_word_char(line[b - 1])) --b;
                if (b == e || std::isdigit(static_cast<unsigned char>(line[b]))) continue;
                size_t d = scan::skip_blanks(line, open + 1), d_end = d;
                while (d_end < line.size() && std::isdigit(static_cast<unsigned char>(line[d_end]))) ++d_end;
                if (d_end == d || scan::skip_blanks(line, d_end) >= line.size() || line[scan::skip_blanks(line, d_end)] != ']') continue;
                unsigned long long count = scan::parse_decimal(std::string_view(line).substr(d, d_end - d), ~0ull).value_or(~0ull);
                if (count > most) {
                    most = count;
                    best = {display_path(f), n, static_cast<int>(b) + 1};
                }
            }
    }
    return best;
}

std::string defines_text(const std::map<std::string, std::string>& defines) {
    std::string s;
    for (const auto& [k, v] : defines) s += "#define " + k + " " + v + "\n";
    return s;
}

} // namespace

Result<Program> compile_program(const std::vector<StageInput>& stages, const CompileOptions& opt) {
    init_glslang();
    Program prog;
    std::vector<std::string> texts;
    std::map<std::string, fs::path> shown_to_disk;
    std::vector<std::string> shown_names;
    for (const auto& st : stages) {
        std::string shown = st.display_name.empty() ? display_path(st.file) : st.display_name;
        std::string text;
        fs::path disk;
        if (!st.source_override.empty()) {
            text = st.source_override;
        } else {
            auto t = read_text(st.file);
            if (!t) {
                Error e = make_error(std::string(stage_name(st.stage)) + " shader file '" + shown + "' cannot be read");
                return e;
            }
            text = std::move(t.value());
            disk = st.file;
        }
        std::string injected = defines_text(opt.defines) + opt.preamble;
        if (auto sp = opt.stage_preamble.find(st.stage); sp != opt.stage_preamble.end()) injected += sp->second;
        auto ex = expand_source(disk, text, shown, injected, opt.include_dirs);
        if (!ex) return ex.error();
        if (!disk.empty()) shown_to_disk[line_name(shown)] = disk;
        for (const auto& f : ex->files) {
            shown_to_disk[line_name(display_path(f))] = f;
            prog.dependencies.push_back(f);
        }
        if (st.stage == Stage::fragment) ex->text += main_image_entry(ex->text);
        texts.push_back(std::move(ex->text));
        shown_names.push_back(line_name(shown));
    }

    // Cache lookup: every expanded text plus stage kinds.
    std::string key_text = "passlab-spirv-v1\n";
    for (size_t i = 0; i < stages.size(); ++i)
        key_text += std::to_string(static_cast<int>(stages[i].stage)) + "\n" + texts[i] + "\n";
    if (!opt.cache_dir.empty()) {
        if (auto cached = cache_load(opt.cache_dir, key_text)) {
            prog.stages = std::move(*cached);
            prog.from_cache = true;
        }
    }

    if (!prog.from_cache) {
        std::vector<std::unique_ptr<glslang::TShader>> shaders;
        glslang::TProgram program;
        EShMessages msgs = static_cast<EShMessages>(EShMsgSpvRules | EShMsgVulkanRules | EShMsgEnhanced);
        // glslang keeps the addresses of these pointer arrays until parse(), so they live here,
        // not in make_shader's frame.
        std::vector<const char*> srcs, names;
        for (size_t i = 0; i < stages.size(); ++i) {
            srcs.push_back(texts[i].c_str());
            names.push_back(shown_names[i].c_str());
        }
        auto make_shader = [&](size_t i) {
            auto sh = std::make_unique<glslang::TShader>(language(stages[i].stage));
            sh->setStringsWithLengthsAndNames(&srcs[i], nullptr, &names[i], 1);
            sh->setEnvInput(glslang::EShSourceGlsl, language(stages[i].stage), glslang::EShClientVulkan, 100);
            sh->setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3);
            sh->setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_6);
            sh->setAutoMapBindings(true);
            sh->setAutoMapLocations(true);
            return sh;
        };
        for (size_t i = 0; i < stages.size(); ++i) {
            auto sh = make_shader(i);
            if (!sh->parse(GetDefaultResources(), 450, false, msgs)) {
                std::string log = sh->getInfoLog();
                // With enhanced messages glslang reports the first error only; a second parse
                // without them, going on past errors that could cascade, finds the later
                // mistakes too, so one reload shows them all. Only its errors on lines the first
                // parse did not name are kept (the rest are follow-ups of the same mistake). Not
                // after a syntax error: what a parser reports past one is mostly its own recovery.
                if (log.find("syntax error") == std::string::npos) {
                    auto again = make_shader(i);
                    again->parse(GetDefaultResources(), 450, false,
                                 static_cast<EShMessages>((msgs & ~EShMsgEnhanced) | EShMsgCascadingErrors));
                    log = merge_later_errors(log, again->getInfoLog());
                }
                return parse_log(log, stages[i].stage, shown_to_disk, shown_names[i], {}, texts[i]);
            }
            program.addShader(sh.get());
            shaders.push_back(std::move(sh));
        }
        if (!program.link(msgs) || !program.mapIO()) {
            std::map<Stage, std::string> stage_files;
            for (size_t i = 0; i < stages.size(); ++i) stage_files[stages[i].stage] = shown_names[i];
            return parse_log(program.getInfoLog(), stages.back().stage, shown_to_disk, shown_names.back(), stage_files);
        }
        for (size_t i = 0; i < stages.size(); ++i) {
            StageSpirv out{stages[i].stage, {}};
            glslang::SpvOptions so;
            so.generateDebugInfo = false;
            so.disableOptimizer = true;
            glslang::GlslangToSpv(*program.getIntermediate(language(stages[i].stage)), out.words, &so);
            prog.stages.push_back(std::move(out));
        }
        unify_bindings(prog.stages);
        if (!opt.cache_dir.empty()) cache_store(opt.cache_dir, key_text, prog.stages);
    }

    for (size_t i = 0; i < prog.stages.size(); ++i) {
        uint64_t bytes = private_memory_bytes(prog.stages[i].words);
        if (bytes > opt.max_private_bytes) {
            Error e = make_error(std::string(stage_name(prog.stages[i].stage)) + " shader needs " +
                                     std::to_string(bytes) + " bytes of private/function-local memory per "
                                     "invocation (limit " + std::to_string(opt.max_private_bytes) +
                                     "): refused, it would exhaust memory",
                                 {shown_names[i], 0, 0});
            // SPIR-V without debug info has no lines: point at the largest array declaration.
            if (SourceLoc at = largest_array_declaration(prog.dependencies); at.known()) {
                e.loc = at;
                e.source_line = read_source_line(at.file, at.line);
            }
            e.hint = "large arrays belong in a storage buffer ([buffers]), not in a local variable";
            return e;
        }
    }

    for (size_t i = 0; i < prog.stages.size(); ++i) {
        if (prog.stages[i].stage != Stage::compute) continue;
        uint64_t bytes = workgroup_memory_bytes(prog.stages[i].words);
        prog.reflection.shared_bytes = bytes;
        // Beyond the guaranteed minimum some device may refuse it: remember where it is declared.
        if (bytes > 16384) prog.reflection.shared_decl = largest_array_declaration(prog.dependencies, "shared");
        if (bytes <= opt.max_shared_bytes) continue;
        Error e = make_error("compute shader declares " + std::to_string(bytes) + " bytes of shared memory; no Vulkan device offers more than " +
                                 std::to_string(opt.max_shared_bytes) + " (maxComputeSharedMemorySize)",
                             {shown_names[i], 0, 0});
        if (prog.reflection.shared_decl.known()) {
            e.loc = prog.reflection.shared_decl;
            e.source_line = read_source_line(e.loc.file, e.loc.line);
        }
        e.hint = "a large array shared by the workgroup belongs in a storage buffer ([buffers])";
        return e;
    }

    // Reflection merged across stages.
    for (const auto& st : prog.stages) {
        auto r = reflect_spirv(st.words, st.stage);
        if (!r) return r.error();
        Reflection& m = prog.reflection;
        for (const auto& b : r->bindings) {
            auto it = std::find_if(m.bindings.begin(), m.bindings.end(),
                                   [&](const Binding& x) { return x.set == b.set && x.binding == b.binding; });
            if (it == m.bindings.end()) m.bindings.push_back(b);
            else if (it->name != b.name)
                return make_error("'" + it->name + "' and '" + b.name + "' share set " + std::to_string(b.set) +
                                  " binding " + std::to_string(b.binding) + " in different stages");
            else it->stages |= b.stages;
        }
        if (r->push_constant_size) {
            m.push_constant_size = std::max(m.push_constant_size, r->push_constant_size);
            m.push_constant_stages |= r->push_constant_stages;
        }
        if (st.stage == Stage::compute)
            for (int k = 0; k < 3; ++k) m.local_size[k] = r->local_size[k];
        if (st.stage == Stage::vertex) m.vertex_input_locations = r->vertex_input_locations;
        if (st.stage == Stage::fragment) m.fragment_output_count = r->fragment_output_count;
    }
    std::sort(prog.reflection.bindings.begin(), prog.reflection.bindings.end(),
              [](const Binding& a, const Binding& b) { return std::tie(a.set, a.binding) < std::tie(b.set, b.binding); });
    std::sort(prog.dependencies.begin(), prog.dependencies.end());
    prog.dependencies.erase(std::unique(prog.dependencies.begin(), prog.dependencies.end()), prog.dependencies.end());
    return prog;
}

const Binding* Reflection::find(const std::string& name) const {
    for (const auto& b : bindings)
        if (b.name == name) return &b;
    return nullptr;
}

} // namespace pl::shader
