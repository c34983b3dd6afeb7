// preset.toml -> GraphDesc. Sections: [preset] [view] [params] [images] [buffers] [meshes]
// [[pass]] [output] [[test]]; every key is checked (unknown keys are errors, not ignored).
#include "graph/parse.hpp"

#include "graph/parse_parts.hpp"
#include "graph/toml_reader.hpp"

#include <algorithm>
#include <fstream>
#include <tuple>
#include <sstream>

namespace fs = std::filesystem;

namespace pl::graph {

namespace {

Status parse_preset(const toml::table& t, const std::string& file, GraphDesc& g) {
    TableReader r(t, file, "[preset]");
    if (auto s = r.str("title", g.meta.title); !s) return s;
    if (auto s = r.str("family", g.meta.family); !s) return s;
    if (auto s = r.str("summary", g.meta.summary); !s) return s;
    if (auto s = r.strings("tags", g.meta.tags); !s) return s;
    return r.finish();
}

Status parse_orbit(TableReader& r, OrbitCamera& o) {
    std::vector<double> target;
    if (auto s = r.numbers("target", target, 3, 3); !s) return s;
    if (!target.empty()) o.target = {float(target[0]), float(target[1]), float(target[2])};
    if (auto s = r.floats("distance", o.distance); !s) return s;
    if (auto s = r.floats("yaw", o.yaw); !s) return s;
    if (auto s = r.floats("pitch", o.pitch); !s) return s;
    if (o.distance <= 0) return r.error("camera distance must be > 0", r.key_loc("distance"));
    return r.finish();
}

Status parse_view(const toml::table& t, const std::string& file, GraphDesc& g) {
    TableReader r(t, file, "[view]");
    g.view.loc = r.loc();
    std::vector<double> size;
    if (auto s = r.numbers("size", size, 2, 2); !s) return s;
    if (!size.empty()) {
        if (size[0] < 1 || size[1] < 1 || size[0] > 16384 || size[1] > 16384)
            return r.error("[view] size must be between 1x1 and 16384x16384", r.key_loc("size"));
        g.view.size = {int(size[0]), int(size[1])};
    }
    if (const toml::node* cam = r.get("camera")) {
        const toml::table* ct = cam->as_table();
        if (!ct) return r.type_error("camera", "a table");
        TableReader c(*ct, file, "[view].camera");
        if (const toml::node* orbit = c.get("orbit")) {
            if (!orbit->as_table()) return c.type_error("orbit", "a table");
            TableReader o(*orbit->as_table(), file, "camera.orbit");
            if (auto s = parse_orbit(o, g.view.orbit); !s) return s;
        }
        if (auto s = c.floats("fov", g.view.fov); !s) return s;
        if (auto s = c.floats("near", g.view.near); !s) return s;
        if (auto s = c.floats("far", g.view.far); !s) return s;
        if (auto s = c.boolean("ortho", g.view.ortho); !s) return s;
        if (auto s = c.floats("ortho_height", g.view.ortho_height); !s) return s;
        if (auto s = c.finish(); !s) return s;
    }
    return r.finish();
}

Status parse_output(const toml::table& t, const std::string& file, GraphDesc& g) {
    TableReader r(t, file, "[output]");
    if (auto s = r.str("image", g.output, &g.output_loc); !s) return s;
    return r.finish();
}

} // namespace

Result<GraphDesc> parse_graph_text(std::string_view text_in, const fs::path& as_file) {
    std::string text(text_in);
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);  // UTF-8 BOM: accepted
    GraphDesc g;
    g.file = fs::absolute(as_file);
    g.dir = g.file.parent_path();
    std::error_code ec;
    std::string file = fs::proximate(as_file, ec).string();
    if (ec) file = as_file.string();
    toml::table root;
    try {
        root = toml::parse(text, file);
    } catch (const toml::parse_error& err) {
        const auto& s = err.source();
        Error e = make_error("invalid TOML: " + std::string(err.description()),
                             {file, static_cast<int>(s.begin.line), static_cast<int>(s.begin.column)});
        // The BOM-stripped text is what was parsed; read the line from it, not the file.
        std::istringstream in(text);
        std::string line;
        for (int n = 1; std::getline(in, line); ++n)
            if (n == static_cast<int>(s.begin.line)) {
                if (!line.empty() && line.back() == '\r') line.pop_back();
                e.source_line = line;
            }
        return e;
    }
    TableReader top(root, file, "preset.toml");
    auto section = [&](const char* key, auto&& fn) -> Status {
        const toml::node* n = top.get(key);
        if (!n) return ok_status();
        const toml::table* t = n->as_table();
        if (!t) return top.type_error(key, "a table ([" + std::string(key) + "])");
        return fn(*t);
    };
    if (auto s = section("preset", [&](const toml::table& t) { return parse_preset(t, file, g); }); !s) return s.error();
    if (auto s = section("view", [&](const toml::table& t) { return parse_view(t, file, g); }); !s) return s.error();
    if (auto s = section("params", [&](const toml::table& t) { return parse_params(t, file, g); }); !s) return s.error();
    if (auto s = section("images", [&](const toml::table& t) { return parse_images(t, file, g); }); !s) return s.error();
    if (auto s = section("buffers", [&](const toml::table& t) { return parse_buffers(t, file, g); }); !s) return s.error();
    if (auto s = section("meshes", [&](const toml::table& t) { return parse_meshes(t, file, g); }); !s) return s.error();
    if (auto s = section("output", [&](const toml::table& t) { return parse_output(t, file, g); }); !s) return s.error();
    auto array_of_tables = [&](const char* key, auto&& fn) -> Status {
        const toml::node* n = top.get(key);
        if (!n) return ok_status();
        const toml::array* a = n->as_array();
        if (!a || !a->is_array_of_tables()) return top.type_error(key, "an array of tables ([[" + std::string(key) + "]])");
        for (const auto& e : *a)
            if (auto s = fn(*e.as_table()); !s) return s;
        return ok_status();
    };
    if (auto s = array_of_tables("pass", [&](const toml::table& t) { return parse_pass(t, file, g); }); !s) return s.error();
    if (auto s = array_of_tables("test", [&](const toml::table& t) { return parse_test(t, file, g); }); !s) return s.error();
    if (auto s = top.finish(); !s) return s.error();
    // toml++ iterates tables in key order; keep the order the user wrote (UI, std140 layout,
    // listing), which is the order of the source positions.
    auto by_position = [](const auto& a, const auto& b) {
        return std::tie(a.loc.line, a.loc.col) < std::tie(b.loc.line, b.loc.col);
    };
    std::stable_sort(g.params.begin(), g.params.end(), by_position);
    std::stable_sort(g.images.begin(), g.images.end(), by_position);
    std::stable_sort(g.buffers.begin(), g.buffers.end(), by_position);
    std::stable_sort(g.meshes.begin(), g.meshes.end(), by_position);
    return g;
}

Result<GraphDesc> parse_graph_file(const fs::path& file) {
    std::ifstream in(file, std::ios::binary);
    if (!in) {
        Error e = make_error("cannot read '" + file.string() + "'");
        e.code = ExitCode::user;
        return e;
    }
    std::stringstream ss;
    ss << in.rdbuf();
    return parse_graph_text(ss.str(), file);
}

} // namespace pl::graph
