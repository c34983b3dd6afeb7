// The section parsers of parse.cpp, one file per group of sections, and the few helpers they
// share. Each fills GraphDesc and returns the first error, located at the offending value.
#pragma once

#include "graph/desc.hpp"
#include "graph/toml_reader.hpp"

#include <toml++/toml.h>

namespace pl::graph {

Status parse_params(const toml::table& t, const std::string& file, GraphDesc& g);     // parse_params.cpp
Status parse_images(const toml::table& t, const std::string& file, GraphDesc& g);     // parse_resources.cpp
Status parse_buffers(const toml::table& t, const std::string& file, GraphDesc& g);    // parse_resources.cpp
Status parse_meshes(const toml::table& t, const std::string& file, GraphDesc& g);     // parse_resources.cpp
Status parse_mesh_simplify(TableReader& mesh, MeshSimplifyDesc& out);              // parse_simplify.cpp
Status parse_pass(const toml::table& t, const std::string& file, GraphDesc& g);       // parse_passes.cpp
Status parse_test(const toml::table& t, const std::string& file, GraphDesc& g);       // parse_tests.cpp
Status parse_group(const toml::table& t, const std::string& file, GraphDesc& g);      // parse_groups.cpp
Status parse_orbit(TableReader& r, OrbitCamera& o);                                   // parse.cpp
// One entry of a test's `checks = [...]` (or of `probes = [...]`, with forced_kind "probe"),
// strictly: the kind's keys only, each type- and range-checked.                      // parse_checks.cpp
Status parse_check(const toml::table& t, TableReader& owner, CheckDesc& c, const char* forced_kind);
Status parse_cameras(const toml::table& t, const std::string& file, GraphDesc& g);    // parse_cameras.cpp
// The keys of one camera, read over `c` (a test's override starts from the graph's camera).
Status parse_camera(TableReader& r, CameraDesc& c);                                   // parse_cameras.cpp

// A GLSL identifier: [A-Za-z_][A-Za-z0-9_]*.
bool is_identifier(const std::string& s);
// Resource and param names become GLSL identifiers: they must be identifiers, not keywords or
// reserved words (glslang rejects those with an error far from the TOML line), and not start
// with "gl_" or contain "__" (reserved by GLSL). `what` is "param", "image", ...
Status check_name(const TableReader& section, const std::string& key, const char* what);

// Passes, tests and groups are referred to by name, so each name is used once per kind: "a
// <kind> named 'x' already exists" at `loc`, with where the first one is written. T has .name
// and .loc.
template <class T>
Status unique_name(const TableReader& r, const std::vector<T>& earlier, const char* kind, const std::string& name,
                   const SourceLoc& loc) {
    for (const auto& other : earlier)
        if (other.name == name) {
            Error e = r.error(std::string("a ") + kind + " named '" + name + "' already exists", loc);
            e.notes.push_back("the first is at " + other.loc.str());
            return e;
        }
    return ok_status();
}

// The compare ops shared by depth tests, stencil faces and comparison samplers.
const std::vector<std::string>& compare_ops();

} // namespace pl::graph
