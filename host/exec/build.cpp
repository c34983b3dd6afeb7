#include "exec/build.hpp"

#include "exec/bind.hpp"
#include "exec/image_override.hpp"
#include "exec/preamble.hpp"
#include "exec/views.hpp"
#include "graph/parse.hpp"
#include "graph/sizeexpr.hpp"
#include "graph/validate.hpp"
#include "shader/include.hpp"
#include "util/paths.hpp"
#include "util/scan.hpp"

#include <algorithm>
#include <cstdlib>

namespace fs = std::filesystem;

namespace pl::exec {

fs::path passes_dir() { return graph::passes_dir(); }  // one definition: graph/validate.cpp

fs::path presets_dir() {
    if (const char* root = std::getenv("PASSLAB_ROOT"); root && *root) return fs::path(root) / "presets";
    return fs::path(PASSLAB_SOURCE_DIR) / "presets";
}

Result<fs::path> resolve_preset(const std::string& arg) {
    std::error_code ec;
    fs::path p(arg);
    if (fs::is_directory(p, ec)) {
        // Normalised, so that "." is named after its folder: `render .` writes <folder>.png, not "..png".
        if (fs::exists(p / "preset.toml", ec)) return fs::absolute(p / "preset.toml").lexically_normal();
        Error e = make_error("folder '" + arg + "' has no preset.toml");
        e.code = ExitCode::user;
        return e;
    }
    if (fs::is_regular_file(p, ec)) {
        // A shader where a preset is expected would otherwise be reported as invalid TOML.
        if (is_shader_file(p)) {
            Error e = make_error("'" + arg + "' looks like a shader file; a preset is a folder with preset.toml (to run a Shadertoy shader use passlab import)");
            e.code = ExitCode::usage;
            if (fs::exists(p.parent_path() / "preset.toml", ec))
                e.hint = "did you mean the preset that holds it, '" + (p.parent_path().empty() ? std::string(".") : p.parent_path().string()) + "'?";
            return e;
        }
        return fs::absolute(p).lexically_normal();
    }
    // A name: family/name or name, under presets/.
    fs::path root = presets_dir();
    if (fs::exists(root / arg / "preset.toml", ec)) return root / arg / "preset.toml";
    std::vector<std::string> names, bare;  // family/name, and name alone (what is typed most)
    if (fs::is_directory(root, ec)) {
        for (const auto& fam : fs::directory_iterator(root, ec)) {
            if (!fam.is_directory()) continue;
            for (const auto& pre : fs::directory_iterator(fam.path(), ec)) {
                if (!fs::exists(pre.path() / "preset.toml", ec)) continue;
                std::string full = fam.path().filename().string() + "/" + pre.path().filename().string();
                if (pre.path().filename() == arg) return pre.path() / "preset.toml";
                names.push_back(full);
                bare.push_back(pre.path().filename().string());
            }
        }
    }
    Error e = make_error("no preset '" + arg + "': not a folder with preset.toml, a .toml file, or "
                         "a preset name");
    std::string near = nearest_name(arg, names);
    if (near.empty()) {
        // "fbmm" is far from "procedural/fbm" but near "fbm": compare the last part alone.
        const std::string last = fs::path(arg).filename().string();
        std::string b = nearest_name(last, bare);
        if (!b.empty()) near = names[static_cast<size_t>(std::find(bare.begin(), bare.end(), b) - bare.begin())];
    }
    if (!near.empty()) e.hint = "did you mean '" + near + "'?";
    e.notes.push_back("`passlab list` shows the presets");
    return e;
}

namespace {

// Looks for `file` in the overlay folders, the preset folder, then passes/.
fs::path find_shader(const std::vector<fs::path>& search, const std::string& file) {
    std::error_code ec;
    for (const auto& d : search)
        if (fs::exists(d / file, ec)) return d / file;
    return search.size() > 1 ? search[search.size() - 2] / file : fs::path(file);
}

Status compile_pass(CompiledGraph& g, CompiledPass& cp, const BuildOptions& opt) {
    const graph::PassDesc& pd = *cp.desc;
    std::vector<shader::StageInput> stages;
    auto add = [&](shader::Stage st, const graph::ShaderRef& ref) {
        if (ref.empty()) return;
        fs::path f = find_shader(g.search_dirs, ref.file);
        stages.push_back({st, f, shader::display_path(f), {}});
    };
    switch (pd.kind) {
    case graph::PassKind::fullscreen:
        if (pd.vertex.empty())
            stages.push_back({shader::Stage::vertex, "<passlab fullscreen.vert>", "<passlab fullscreen.vert>",
                              fullscreen_vertex_source()});
        else
            add(shader::Stage::vertex, pd.vertex);
        add(shader::Stage::fragment, pd.fragment);
        break;
    case graph::PassKind::draw:
        add(shader::Stage::vertex, pd.vertex);
        add(shader::Stage::tess_control, pd.tess_control);
        add(shader::Stage::tess_eval, pd.tess_eval);
        add(shader::Stage::geometry, pd.geometry);
        add(shader::Stage::fragment, pd.fragment);
        break;
    case graph::PassKind::compute: add(shader::Stage::compute, pd.compute); break;
    default: return ok_status();  // transfer kinds have no shaders
    }

    shader::CompileOptions co;
    for (const auto& d : g.search_dirs) co.include_dirs.push_back(d);
    co.preamble = preamble_source(g.desc.params, g.desc.cameras);
    co.defines = pd.defines;
    co.cache_dir = opt.cache_dir;
    auto prog = shader::compile_program(stages, co);
    if (!prog) {
        Error e = prog.error();
        if (e.pass.empty()) e.pass = pd.name;
        // A line that uses one of the pass's defines most likely fails because of its value
        // (set in preset.toml, while the line may be in a library shader): blame the define.
        for (const auto& [name, value] : pd.defines) {
            if (scan::find_word(e.source_line, name) == std::string::npos) continue;
            SourceLoc at = pd.keys.at("defines." + name, pd.loc);
            e.notes.insert(e.notes.begin(), "where it is used: " + e.loc.str() + ": " + e.source_line);
            e.message += " (with " + name + " = " + value + ")";
            e.loc = at;
            e.source_line = read_source_line(at.file, at.line);
            break;
        }
        return e;
    }
    cp.program = std::move(prog.value());
    for (const auto& d : cp.program.dependencies) g.dependencies.push_back(d);
    return ok_status();
}

} // namespace

Result<CompiledGraph> build_graph(const fs::path& preset_toml, const BuildOptions& opt) {
    auto parsed = graph::parse_graph_file(preset_toml);
    if (!parsed) return parsed.error();
    CompiledGraph g;
    g.desc = std::move(parsed.value());
    g.dependencies.push_back(g.desc.file);

    for (const auto& s : opt.set) {
        if (auto img = apply_image_override(g.desc, s)) {
            if (!*img) return img->error();
            continue;
        }
        if (auto st = apply_param_override(g.desc.params, s); !st) return st.error();
    }
    for (const auto& [name, value] : opt.set_values)
        if (auto st = apply_param_value(g.desc.params, name, value, {}); !st) return st.error();
    for (auto& c : g.desc.cameras)
        if (auto it = opt.cameras.find(c.name); it != opt.cameras.end()) c = it->second;
    if (opt.size) g.desc.view.size = *opt.size;
    g.view = g.desc.view.size;

    for (const auto& d : opt.overlay_dirs) g.search_dirs.push_back(canonical_or_normal(d));
    g.search_dirs.push_back(g.desc.dir);
    g.search_dirs.push_back(passes_dir());

    graph::ValidateOptions vo;
    vo.search_dirs = g.search_dirs;
    vo.test_reads = !opt.size && opt.set.empty() && opt.set_values.empty();
    if (auto st = graph::validate_graph(g.desc, vo); !st) return st.error();

    g.param_layout = layout_params(g.desc.params);
    graph::SizeEnv env = size_env(g.desc, g.view);

    g.passes.resize(g.desc.passes.size());
    for (size_t i = 0; i < g.desc.passes.size(); ++i) {
        CompiledPass& cp = g.passes[i];
        cp.desc = &g.desc.passes[i];
        if (!cp.desc->repeat.empty()) {
            auto r = graph::eval_scalar(cp.desc->repeat, env);
            if (!r) {
                Error e = r.error();
                e.pass = cp.desc->name;
                return e;
            }
            if (*r < 1 || *r > 4096) {
                Error e = make_error("repeat evaluates to " + std::to_string(*r) +
                                         "; it must be between 1 and 4096",
                                     cp.desc->repeat.loc);
                e.pass = cp.desc->name;
                return e;
            }
            cp.repeat = static_cast<int>(*r);
        }
        if (!cp.desc->enabled_when.empty()) {
            // Evaluated every frame by the executor; here once, so a wrong name fails the build.
            if (auto r = graph::eval_scalar(cp.desc->enabled_when, env); !r) {
                Error e = r.error();
                e.pass = cp.desc->name;
                return e;
            }
        }
        if (auto st = compile_pass(g, cp, opt); !st) return st.error();
        if (auto st = bind_pass(g.desc, cp); !st) return st.error();
    }

    for (const auto& img : g.desc.images)
        if (!img.file.empty()) g.dependencies.push_back(g.desc.dir / img.file);
    for (const auto& m : g.desc.meshes)
        if (!m.file.empty()) g.dependencies.push_back(g.desc.dir / m.file);
    std::sort(g.dependencies.begin(), g.dependencies.end());
    g.dependencies.erase(std::unique(g.dependencies.begin(), g.dependencies.end()), g.dependencies.end());

    // Groups: each member knows its group; the group's count is evaluated like a pass's repeat.
    for (size_t k = 0; k < g.desc.groups.size(); ++k) {
        const graph::GroupDesc& gd = g.desc.groups[k];
        CompiledGroup cg;
        cg.desc = &gd;
        if (!gd.repeat.empty()) {
            auto r = graph::eval_scalar(gd.repeat, env);
            if (!r) return r.error();
            cg.repeat = static_cast<int>(*r);  // 1..4096: checked with the sizes
        }
        for (const auto& name : gd.passes)
            for (size_t i = 0; i < g.passes.size(); ++i)
                if (g.passes[i].desc->name == name) {
                    cg.members.push_back(i);
                    g.passes[i].group = static_cast<int>(k);
                }
        g.groups.push_back(std::move(cg));
    }
    for (auto& cp : g.passes) {
        int group_repeat = cp.group >= 0 ? g.groups[static_cast<size_t>(cp.group)].repeat : 1;
        if (int64_t(group_repeat) * cp.repeat > 65536) {
            Error e = make_error("pass '" + cp.desc->name + "' would run " + std::to_string(int64_t(group_repeat) * cp.repeat) +
                                     " times a frame (its repeat " + std::to_string(cp.repeat) + " x its group's " +
                                     std::to_string(group_repeat) + "); the limit is 65536",
                                 cp.desc->repeat.loc.known() ? cp.desc->repeat.loc : cp.desc->loc);
            e.pass = cp.desc->name;
            return e;
        }
        if (auto st = resolve_views(g.desc, env, cp, group_repeat); !st) return st.error();
    }

    // The planner sees a group as one unit: the union of its members' reads and writes, at the
    // position of its first member; its members then run contiguously in the listed order.
    std::vector<PlanPass> plan;
    std::vector<int> unit_group;  // per plan unit: the group it stands for, or -1
    std::vector<size_t> unit_pass;
    std::vector<int> group_unit(g.groups.size(), -1);
    for (size_t i = 0; i < g.passes.size(); ++i) {
        const CompiledPass& cp = g.passes[i];
        PlanPass* unit = nullptr;
        if (cp.group >= 0) {
            int& u = group_unit[static_cast<size_t>(cp.group)];
            if (u < 0) {
                const graph::GroupDesc& gd = *g.groups[static_cast<size_t>(cp.group)].desc;
                u = static_cast<int>(plan.size());
                plan.push_back({gd.name, gd.loc, {}, {}, true});
                unit_group.push_back(cp.group);
                unit_pass.push_back(i);
            }
            unit = &plan[static_cast<size_t>(u)];
        } else {
            plan.push_back({cp.desc->name, cp.desc->loc, {}, {}});
            unit_group.push_back(-1);
            unit_pass.push_back(i);
            unit = &plan.back();
        }
        if (!cp.desc->enabled) continue;
        unit->reads.insert(unit->reads.end(), cp.io.reads.begin(), cp.io.reads.end());
        unit->writes.insert(unit->writes.end(), cp.io.writes.begin(), cp.io.writes.end());
    }
    // A group's swap partners trade roles every iteration: the group reads and writes both.
    for (size_t k = 0; k < g.groups.size(); ++k)
        if (group_unit[k] >= 0)
            for (const auto& n : g.groups[k].desc->swap) {
                plan[static_cast<size_t>(group_unit[k])].reads.push_back(n);
                plan[static_cast<size_t>(group_unit[k])].writes.push_back(n);
            }
    auto order = order_passes(plan);
    if (!order) return order.error();
    for (size_t u : *order) {
        if (unit_group[u] < 0) g.order.push_back(unit_pass[u]);
        else
            for (size_t m : g.groups[static_cast<size_t>(unit_group[u])].members) g.order.push_back(m);
    }
    return g;
}

} // namespace pl::exec
