// `passlab check`: everything up to (not including) the GPU: parse, validate, compile, reflect,
// bind by name, plan. Needs no Vulkan device, so it runs anywhere and fast.
#include "verbs.hpp"
#include "sources.hpp"

#include "exec/build.hpp"

#include <chrono>
#include <cstdio>
#include <filesystem>
#include <fstream>

namespace pl::lab {

int check(const std::string& preset, const std::vector<std::string>& set, const CommonOptions& c,
          const std::string& spirv_dir) {
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
    describe_exercise(c, *built);
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (!spirv_dir.empty()) {
        // <pass>.<stage>.spv, exactly what the executor would hand to the driver.
        std::filesystem::create_directories(spirv_dir);
        for (const auto& p : built->passes)
            for (const auto& st : p.program.stages) {
                auto file = std::filesystem::path(spirv_dir) / (p.desc->name + "." + shader::stage_name(st.stage) + ".spv");
                std::ofstream out(file, std::ios::binary);
                out.write(reinterpret_cast<const char*>(st.words.data()), static_cast<std::streamsize>(st.words.size() * 4));
                std::printf("%s\n", file.string().c_str());
            }
    }
    std::printf("ok: %s: %zu pass(es), %zu image(s), %zu buffer(s), %zu file(s) read, %zu test build(s), %.1f ms\n",
                toml->string().c_str(), built->passes.size(), built->desc.images.size(),
                built->desc.buffers.size(), built->dependencies.size(), test_builds, ms);
    return 0;
}

} // namespace pl::lab
