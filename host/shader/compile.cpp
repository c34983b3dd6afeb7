// glslang front end: expanded sources of all stages of a pass are parsed and linked into one
// program, so auto-mapped bindings agree across stages; errors are parsed back into pl::Error
// with the real file and line (from our #line directives) and a column found from the quoted
// token; SPIR-V is reflected and guarded against absurd private memory.
#include "shader/bindings.hpp"
#include "shader/cache.hpp"
#include "shader/entry.hpp"
#include "shader/include.hpp"
#include "shader/program.hpp"

#include <glslang/Public/ResourceLimits.h>
#include <glslang/Public/ShaderLang.h>
#include <glslang/SPIRV/GlslangToSpv.h>

#include <memory>
#include <mutex>
#include <algorithm>
#include <regex>
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

// "ERROR: path:line: 'tok' : message" -> Error at path:line:col with the source line.
Error parse_log(const std::string& log, Stage stage, const std::map<std::string, fs::path>& files,
                const std::string& fallback_file) {
    static const std::regex line_re(R"(^(ERROR|WARNING): (.+?):(\d+): (.*)$)");
    std::vector<Error> errors;
    std::istringstream in(log);
    std::string line;
    std::vector<std::string> other;
    while (std::getline(in, line)) {
        std::smatch m;
        if (std::regex_match(line, m, line_re) && m[1] == "ERROR") {
            std::string file = m[2], msg = m[4];
            while (!msg.empty() && msg.back() == ' ') msg.pop_back();
            int ln = std::stoi(m[3]);
            Error e;
            e.message = std::string(stage_name(stage)) + " shader: " + msg;
            auto f = files.find(file);
            std::string disk = f != files.end() ? f->second.string() : file;
            e.loc = {file, ln, 0};
            e.source_line = read_source_line(disk, ln);
            // Column: the first quoted token of the message, found in the source line.
            static const std::regex tok(R"('([^']+)')");
            std::smatch t;
            if (std::regex_search(msg, t, tok) && !e.source_line.empty()) {
                auto p = e.source_line.find(t[1].str());
                if (p != std::string::npos) e.loc.col = static_cast<int>(p) + 1;
            }
            // Syntax errors quote nothing ("'' : syntax error, unexpected IF, expecting ..."):
            // the unexpected token is a keyword written in capitals; find it as a word.
            static const std::regex unexpected(R"(syntax error, unexpected ([A-Z_0-9]+))");
            std::smatch u;
            if (e.loc.col == 0 && std::regex_search(msg, u, unexpected) && !e.source_line.empty()) {
                std::string word = u[1].str();
                std::transform(word.begin(), word.end(), word.begin(), [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
                std::smatch w;
                if (std::regex_search(e.source_line, w, std::regex("\\b" + word + "\\b")))
                    e.loc.col = static_cast<int>(w.position(0)) + 1;
                // The token is only where the parser noticed; the mistake is usually just before.
                if (msg.find("expecting COMMA or SEMICOLON") != std::string::npos)
                    e.hint = "a ';' is probably missing at the end of the statement before this line";
            }
            errors.push_back(std::move(e));
        } else if (line.rfind("ERROR: ", 0) == 0 && line.find("compilation errors") == std::string::npos) {
            other.push_back(line.substr(7));
        }
    }
    if (errors.empty()) {
        Error e = make_error(std::string(stage_name(stage)) + " shader: " +
                                 (other.empty() ? std::string("glslang failed without a message") : other.front()),
                             {fallback_file, 0, 0});
        for (size_t i = 1; i < other.size() && i < 10; ++i) e.notes.push_back(other[i]);
        return e;
    }
    Error first = errors.front();
    for (size_t i = 1; i < errors.size() && i < 10; ++i)
        first.notes.push_back(errors[i].loc.str() + ": " + errors[i].message);
    return first;
}

// The line declaring the array with the most elements (`name[12345]`) among `files`.
SourceLoc largest_array_declaration(const std::vector<fs::path>& files) {
    static const std::regex decl(R"(\b[A-Za-z_]\w*\s*\[\s*(\d+)\s*\])");
    SourceLoc best;
    unsigned long long most = 0;
    for (const auto& f : files) {
        auto text = read_text(f);
        if (!text) continue;
        std::istringstream in(*text);
        std::string line;
        for (int n = 1; std::getline(in, line); ++n)
            for (std::sregex_iterator it(line.begin(), line.end(), decl), end; it != end; ++it) {
                unsigned long long count = std::stoull((*it)[1].str().substr(0, 18));
                if (count > most) {
                    most = count;
                    best = {display_path(f), n, static_cast<int>(it->position(0)) + 1};
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
        if (!disk.empty()) shown_to_disk[shown] = disk;
        for (const auto& f : ex->files) {
            shown_to_disk[display_path(f)] = f;
            prog.dependencies.push_back(f);
        }
        if (st.stage == Stage::fragment) ex->text += main_image_entry(ex->text);
        texts.push_back(std::move(ex->text));
        shown_names.push_back(shown);
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
        for (size_t i = 0; i < stages.size(); ++i) {
            auto sh = std::make_unique<glslang::TShader>(language(stages[i].stage));
            const char* src = texts[i].c_str();
            const char* name = shown_names[i].c_str();
            sh->setStringsWithLengthsAndNames(&src, nullptr, &name, 1);
            sh->setEnvInput(glslang::EShSourceGlsl, language(stages[i].stage), glslang::EShClientVulkan, 100);
            sh->setEnvClient(glslang::EShClientVulkan, glslang::EShTargetVulkan_1_3);
            sh->setEnvTarget(glslang::EShTargetSpv, glslang::EShTargetSpv_1_6);
            sh->setAutoMapBindings(true);
            sh->setAutoMapLocations(true);
            if (!sh->parse(GetDefaultResources(), 450, false, msgs))
                return parse_log(sh->getInfoLog(), stages[i].stage, shown_to_disk, shown_names[i]);
            program.addShader(sh.get());
            shaders.push_back(std::move(sh));
        }
        if (!program.link(msgs) || !program.mapIO())
            return parse_log(program.getInfoLog(), stages.back().stage, shown_to_disk, shown_names.back());
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
