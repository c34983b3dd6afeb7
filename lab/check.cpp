// `passlab check`: everything up to (not including) the GPU: parse, validate, compile, reflect,
// bind by name, plan. Needs no Vulkan device, so it runs anywhere and fast.
#include "verbs.hpp"
#include "sources.hpp"

#include "check_json.hpp"
#include "exec/build.hpp"
#include "scene/mesh.hpp"

#include <nlohmann/json.hpp>

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace pl::lab {

int check(const std::string& preset, const std::vector<std::string>& set, const CommonOptions& c,
          const std::string& spirv_dir, const std::string& json_file) {
    if (!json_file.empty() && json_file != "-")
        if (auto s = check_output_file(json_file, "--json"); !s) return report(s.error());
    auto t0 = std::chrono::steady_clock::now();
    auto toml = resolve_source(preset);
    if (!toml) return report(toml.error());
    exec::BuildOptions bo;
    bo.set = set;
    bo.cache_dir = cache_dir(c);
    auto overlay = exercise_overlay(c);
    if (!overlay) return report(overlay.error());
    bo.overlay_dirs = *overlay;
    auto built = exec::build_graph(*toml, bo);
    if (!built) return report(built.error());
    // Each test that changes the size, params or cameras builds again with them, as `test` will:
    // what depends on them (repeat counts, per-iteration mip and layer selections, attachment
    // sizes at a level) is known only then, and `check` should not pass what `test` refuses.
    size_t test_builds = 0;
    for (const auto& t : built->desc.tests) {
        if (!t.size && t.set.empty() && t.cameras.empty()) continue;
        exec::BuildOptions tb = bo;
        if (t.size) tb.size = *t.size;
        tb.set_values = t.set;
        tb.cameras = t.cameras;
        auto per_test = exec::build_graph(*toml, tb);
        if (!per_test) {
            Error e = per_test.error();
            e.notes.push_back("in test '" + t.name + "' (" + t.loc.str() + "), which builds the graph with its own size, set and cameras");
            return report(e);
        }
        ++test_builds;
    }
    // Mesh files are read by the executor, on the GPU path; read them here too, so that a
    // broken or hostile mesh (a device file, a face of 200,000 corners) is refused by `check`.
    for (const auto& md : built->desc.meshes) {
        if (md.file.empty()) continue;
        if (auto m = scene::load_mesh(built->desc.dir / md.file); !m) {
            Error e = m.error();
            if (!e.loc.known()) e.loc = md.loc;
            e.resource = md.name;
            return report(e);
        }
    }
    describe_exercise(c, *built);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!spirv_dir.empty()) {
        // <pass>.<stage>.spv, exactly what the executor would hand to the driver.
        std::error_code ec;
        std::filesystem::create_directories(spirv_dir, ec);
        if (ec || !std::filesystem::is_directory(spirv_dir, ec)) {
            Error e = make_error("--spirv " + spirv_dir + ": cannot create that folder" + (ec ? ": " + ec.message() : " (a file of that name exists)"));
            e.code = ExitCode::environment;
            return report(e);
        }
        for (const auto& p : built->passes)
            for (const auto& st : p.program.stages) {
                auto file = std::filesystem::path(spirv_dir) / (p.desc->name + "." + shader::stage_name(st.stage) + ".spv");
                std::ofstream out(file, std::ios::binary);
                out.write(reinterpret_cast<const char*>(st.words.data()), static_cast<std::streamsize>(st.words.size() * 4));
                if (!out) {
                    Error e = make_error("--spirv: cannot write '" + file.string() + "'");
                    e.code = ExitCode::environment;
                    return report(e);
                }
                std::printf("%s\n", file.string().c_str());
            }
    }
    if (!json_file.empty()) {
        const std::string text = describe_graph(*built).dump(2) + "\n";
        if (json_file == "-") {
            std::fputs(text.c_str(), stdout);
            return 0;  // stdout is the JSON alone, for pipes
        }
        std::ofstream out(json_file, std::ios::trunc);
        out << text;
        out.close();
        if (!out) {
            Error e = make_error("--json " + json_file + ": cannot write");
            e.code = ExitCode::environment;
            return report(e);
        }
    }
    std::printf("ok: %s: %zu pass(es), %zu image(s), %zu buffer(s), %zu file(s) read, %zu test build(s), %.1f ms\n",
                toml->string().c_str(), built->passes.size(), built->desc.images.size(),
                built->desc.buffers.size(), built->dependencies.size(), test_builds, ms);
    return 0;
}

} // namespace pl::lab
