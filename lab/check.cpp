// `passlab check`: everything up to (not including) the GPU: parse, validate, compile, reflect,
// bind by name, plan. Needs no Vulkan device, so it runs anywhere and fast.
#include "verbs.hpp"

#include "exec/build.hpp"

#include <chrono>
#include <cstdio>

namespace pl::lab {

int check(const std::string& preset, const std::vector<std::string>& set, const CommonOptions& c) {
    auto t0 = std::chrono::steady_clock::now();
    auto toml = exec::resolve_preset(preset);
    if (!toml) return report(toml.error());
    exec::BuildOptions bo;
    bo.set = set;
    bo.cache_dir = cache_dir(c);
    auto built = exec::build_graph(*toml, bo);
    if (!built) return report(built.error());
    double ms = std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    std::printf("ok: %s: %zu pass(es), %zu image(s), %zu buffer(s), %zu file(s) read, %.1f ms\n",
                toml->string().c_str(), built->passes.size(), built->desc.images.size(),
                built->desc.buffers.size(), built->dependencies.size(), ms);
    return 0;
}

} // namespace pl::lab
