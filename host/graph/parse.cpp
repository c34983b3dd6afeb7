// preset.toml -> GraphDesc. Sections: [preset] [view] [params] [cameras] [images] [buffers] [meshes]
// [[pass]] [output] [[test]]; every key is checked (an unknown key is an error, not ignored: a
// typo such as `fromat` must not silently fall back to a default).
#include "graph/parse.hpp"
#include "graph/course_docs.hpp"

#include "graph/parse_parts.hpp"
#include "util/files.hpp"

#include <algorithm>
#include <cmath>
#include <sstream>
#include <tuple>

namespace fs = std::filesystem;

namespace pl::graph {

Status parse_orbit(TableReader& r, OrbitCamera& o) {
    std::vector<double> target;
    if (auto s = r.numbers("target", target, 3, 3); !s) return s;
    if (!target.empty()) o.target = {float(target[0]), float(target[1]), float(target[2])};
    if (auto s = r.floats("distance", o.distance); !s) return s;
    if (auto s = r.floats("yaw", o.yaw); !s) return s;
    if (auto s = r.floats("pitch", o.pitch); !s) return s;
    if (!(o.distance > 0)) return r.error(r.what() + ": distance must be > 0", r.value_loc("distance"));
    return r.finish();
}

namespace {

Status parse_preset(const toml::table& t, const std::string& file, GraphDesc& g) {
    TableReader r(t, file, "[preset]");
    if (auto s = r.str("title", g.meta.title); !s) return s;
    if (auto s = r.str("family", g.meta.family); !s) return s;
    if (auto s = r.str("summary", g.meta.summary); !s) return s;
    if (auto s = r.strings("tags", g.meta.tags); !s) return s;
    if (r.has("level"))
        if (auto s = r.choice("level", g.meta.level, {"core", "extended"}); !s) return s;
    if (auto s = r.strings("sources", g.meta.sources); !s) return s;
    // Each citation names a document the project describes (docs/references.md) and lines it has.
    if (r.has("sources")) {
        const auto* arr = t["sources"].as_array();
        for (size_t k = 0; k < g.meta.sources.size(); ++k) {
            auto c = parse_citation(g.meta.sources[k]);
            if (!c) {
                Error e = c.error();
                e.loc = r.loc_of(*arr->get(k));
                return e;
            }
        }
    }
    if (auto s = r.str("invariant", g.meta.invariant); !s) return s;
    if (auto s = r.str("author", g.meta.author); !s) return s;
    if (auto s = r.str("license", g.meta.license); !s) return s;
    if (auto s = r.str("source", g.meta.source); !s) return s;
    return r.finish();
}

// [w, h] of integers in 1..16384: the view and test sizes.
Status view_size(TableReader& r, const std::string& key, std::optional<std::array<int, 2>>& out) {
    std::vector<int64_t> size;
    if (auto s = r.integers(key, size, 2, 2); !s) return s;
    if (size.empty()) return ok_status();
    if (size[0] < 1 || size[1] < 1 || size[0] > 16384 || size[1] > 16384)
        return r.error(r.what() + ": size " + std::to_string(size[0]) + "x" + std::to_string(size[1]) +
                           " is outside 1x1 .. 16384x16384",
                       r.value_loc(key));
    out = std::array<int, 2>{int(size[0]), int(size[1])};
    return ok_status();
}

Status parse_view(const toml::table& t, const std::string& file, GraphDesc& g) {
    TableReader r(t, file, "[view]");
    g.view.loc = r.loc();
    std::optional<std::array<int, 2>> size;
    if (auto s = view_size(r, "size", size); !s) return s;
    if (size) g.view.size = *size;
    auto cam = r.table("camera");
    if (!cam) return cam.error();
    if (*cam) {
        TableReader c(**cam, file, "[view].camera");
        auto orbit = c.table("orbit");
        if (!orbit) return orbit.error();
        if (*orbit) {
            TableReader o(**orbit, file, "camera.orbit");
            if (auto s = parse_orbit(o, g.view.orbit); !s) return s;
        }
        if (auto s = c.floats("fov", g.view.fov); !s) return s;
        if (auto s = c.floats("near", g.view.near); !s) return s;
        if (auto s = c.floats("far", g.view.far, /*allow_inf=*/true); !s) return s;
        if (auto s = c.boolean("ortho", g.view.ortho); !s) return s;
        if (auto s = c.floats("ortho_height", g.view.ortho_height); !s) return s;
        if (!(g.view.fov > 0 && g.view.fov < 180)) return c.error("camera: fov must be between 0 and 180 degrees", c.value_loc("fov"));
        if (!(g.view.near > 0)) return c.error("camera: near must be > 0", c.value_loc("near"));
        if (!(g.view.far > g.view.near)) return c.error("camera: far must be greater than near", c.value_loc("far"));
        // far = inf is an infinite perspective (scene/camera.cpp); an ortho volume must end.
        if (g.view.ortho && std::isinf(g.view.far))
            return c.error("camera: an ortho camera needs a finite far (far = inf is for perspective cameras)", c.value_loc("far"));
        if (!(g.view.ortho_height > 0)) return c.error("camera: ortho_height must be > 0", c.value_loc("ortho_height"));
        if (auto s = c.finish(); !s) return s;
    }
    return r.finish();
}

Status parse_output(const toml::table& t, const std::string& file, GraphDesc& g) {
    TableReader r(t, file, "[output]");
    if (auto s = r.str("image", g.output, &g.output_loc); !s) return s;
    if (r.has("image") && g.output.empty()) return r.error("[output]: image must name an image", g.output_loc);
    return r.finish();
}

} // namespace

Result<GraphDesc> parse_graph_text(std::string_view text_in, const fs::path& as_file) {
    std::string text(text_in);
    // Editors on Windows write a UTF-8 byte-order mark. toml++ 3.3 skips it too, but stripping it
    // here keeps it out of the source lines quoted in errors and does not depend on the parser.
    if (text.rfind("\xEF\xBB\xBF", 0) == 0) text.erase(0, 3);
    GraphDesc g;
    std::error_code abs_ec;
    g.file = fs::absolute(as_file, abs_ec);
    g.dir = g.file.parent_path();
    // Messages name the file as the user would type it: relative to the working directory.
    std::error_code ec;
    std::string file = fs::proximate(as_file, ec).string();
    if (ec || file.empty()) file = as_file.string();
    toml::table root;
    try {
        root = toml::parse(text, file);
    } catch (const toml::parse_error& err) {
        const auto& s = err.source();
        Error e = make_error("invalid TOML: " + std::string(err.description()),
                             {file, static_cast<int>(s.begin.line), static_cast<int>(s.begin.column)});
        // The text parsed may not be the file on disk (BOM stripped, or parse_graph_text on a
        // string): take the offending line from the text itself.
        e.source_line.clear();
        std::istringstream in(text);
        std::string line;
        for (int n = 1; std::getline(in, line); ++n)
            if (n == static_cast<int>(s.begin.line)) {
                if (!line.empty() && line.back() == '\r') line.pop_back();
                e.source_line = line;
                break;
            }
        return e;
    }
    TableReader top(root, file, "preset.toml");
    // Unknown sections first: a misspelt [imgaes] is the cause of whatever else would fail.
    if (auto s = top.finish({"preset", "view", "params", "cameras", "images", "buffers", "meshes", "output", "pass", "group", "test"}); !s)
        return s.error();  // e.g. [[passes]]: "did you mean 'pass'?"
    auto section = [&](const char* key, auto&& fn) -> Status {
        const toml::node* n = top.get(key);
        if (!n) return ok_status();
        const toml::table* t = n->as_table();
        if (!t) return top.type_error(key, "a table ([" + std::string(key) + "])");
        return fn(*t);
    };
    auto array_of_tables = [&](const char* key, auto&& fn) -> Status {
        const toml::node* n = top.get(key);
        if (!n) return ok_status();
        const toml::array* a = n->as_array();
        if (!a || !a->is_array_of_tables()) return top.type_error(key, "an array of tables ([[" + std::string(key) + "]])");
        for (const auto& e : *a)
            if (auto s = fn(*e.as_table()); !s) return s;
        return ok_status();
    };
    // [view] before [[test]] (a test camera starts from the view's); [params] before everything
    // that may name a param.
    Status st = section("preset", [&](const toml::table& t) { return parse_preset(t, file, g); });
    if (st) st = section("view", [&](const toml::table& t) { return parse_view(t, file, g); });
    if (st) st = section("params", [&](const toml::table& t) { return parse_params(t, file, g); });
    if (st) st = section("cameras", [&](const toml::table& t) { return parse_cameras(t, file, g); });
    if (st) st = section("images", [&](const toml::table& t) { return parse_images(t, file, g); });
    if (st) st = section("buffers", [&](const toml::table& t) { return parse_buffers(t, file, g); });
    if (st) st = section("meshes", [&](const toml::table& t) { return parse_meshes(t, file, g); });
    if (st) st = section("output", [&](const toml::table& t) { return parse_output(t, file, g); });
    if (st) st = array_of_tables("pass", [&](const toml::table& t) { return parse_pass(t, file, g); });
    if (st) st = array_of_tables("group", [&](const toml::table& t) { return parse_group(t, file, g); });
    if (st) st = array_of_tables("test", [&](const toml::table& t) { return parse_test(t, file, g); });
    if (!st) return st.error();
    // toml++ iterates tables in key order; keep the order the user wrote (UI, std140 layout,
    // listing), which is the order of the source positions.
    auto by_position = [](const auto& a, const auto& b) {
        return std::tie(a.loc.line, a.loc.col) < std::tie(b.loc.line, b.loc.col);
    };
    std::stable_sort(g.params.begin(), g.params.end(), by_position);
    std::stable_sort(g.images.begin(), g.images.end(), by_position);
    std::stable_sort(g.buffers.begin(), g.buffers.end(), by_position);
    std::stable_sort(g.meshes.begin(), g.meshes.end(), by_position);
    std::stable_sort(g.cameras.begin(), g.cameras.end(), by_position);
    return g;
}

Result<GraphDesc> parse_graph_file(const fs::path& file) {
    // A FIFO or /dev/zero as preset.toml would block or read without end: regular files only.
    auto text = read_file_capped(file, max_text_bytes, "preset");
    if (!text) return text.error();
    return parse_graph_text(*text, file);
}

} // namespace pl::graph
