#include "exec/image_override.hpp"

#include <algorithm>
#include <filesystem>

namespace fs = std::filesystem;

namespace pl::exec {

std::optional<Status> apply_image_override(graph::GraphDesc& g, const std::string& assignment) {
    const auto eq = assignment.find('=');
    if (eq == std::string::npos) return std::nullopt;  // the param parser reports the syntax
    const std::string name = assignment.substr(0, eq), value = assignment.substr(eq + 1);
    if (std::any_of(g.params.begin(), g.params.end(), [&](const graph::ParamDesc& p) { return p.name == name; }))
        return std::nullopt;
    auto it = std::find_if(g.images.begin(), g.images.end(), [&](const graph::ImageDesc& d) { return d.name == name; });
    if (it == g.images.end()) {
        // Neither: one error that suggests from both lists (a misspelt image would otherwise be
        // reported as an unknown param with only the params listed).
        std::vector<std::string> names, images;
        for (const auto& p : g.params) names.push_back(p.name);
        for (const auto& d : g.images)
            if (!d.file.empty() || !d.generator.empty()) images.push_back(d.name), names.push_back(d.name);
        if (images.empty()) return std::nullopt;  // the param parser's own message says it all
        Error e = make_error("--set " + assignment + ": no param or file image is named '" + name + "'");
        e.code = ExitCode::usage;
        suggest(e, name, names, "params and file/generator images");
        return std::optional<Status>(Status(e));
    }
    graph::ImageDesc& d = *it;
    // No source location: the mistake is on the command line (an imported source's preset.toml
    // is a scratch file the user never wrote).
    auto fail = [&](const std::string& why) {
        Error e = make_error("--set " + assignment + ": " + why);
        e.code = ExitCode::usage;
        e.resource = d.name;
        return std::optional<Status>(Status(e));
    };
    if (d.file.empty() && d.generator.empty())
        return fail("image '" + name + "' is rendered by the graph; --set NAME=FILE replaces file and generator images only");
    if (d.kind != graph::ImageKind::tex2d || d.layers != 1)
        return fail("image '" + name + "' is not a single 2D image; only 2D images take a file from the command line");
    std::error_code ec;
    const fs::path file = fs::absolute(value, ec);
    if (value.empty() || ec || !fs::is_regular_file(file, ec))
        return fail("no such image file '" + value + "' (PNG, JPG, EXR or HDR; relative to the current directory)");
    // The file decides the size; what the preset says about sampling and upload stays.
    d.file = file.lexically_normal().string();
    d.generator.clear();
    d.generator_args.clear();
    d.size = {};
    return std::optional<Status>(ok_status());
}

} // namespace pl::exec
