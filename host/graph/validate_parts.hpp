// Shared between validate.cpp, validate_passes.cpp and validate_sizes.cpp.
#pragma once

#include "graph/validate.hpp"

namespace pl::graph {

// The declared names, for "did you mean" and the notes listing valid names.
struct DeclaredNames {
    std::vector<std::string> images, buffers, meshes, params;
    std::vector<std::string> resources() const;  // images then buffers
};

// "<what> '<name>' does not exist", with the suggestion and the list of declared names.
Error ref_error(const std::string& what, const std::string& name, const SourceLoc& loc, const std::string& pass,
                const std::vector<std::string>& valid, const std::string& label);
// "12.5 GiB", "3.0 MiB", "20 bytes".
std::string human_bytes(double bytes);

// The names one check of test `t` refers to (images, buffers, params) exist and have the right
// kind; an `expect` expression evaluates at `env`.                                  validate_checks.cpp
Status validate_check(const GraphDesc& g, const DeclaredNames& n, const TestDesc& t, const CheckDesc& c, const SizeEnv& env);
// What test `t` reads exists at `env` (its size and overrides): the level and layer of every
// image it or a check looks at, probe texels, and the elements of every buffer check.
Status validate_test_reads(const GraphDesc& g, const TestDesc& t, const SizeEnv& env);
Status validate_passes(const GraphDesc& g, const ValidateOptions& opt, const DeclaredNames& names);
Status validate_groups(const GraphDesc& g, const DeclaredNames& names);  // validate_groups.cpp
// Every size of the graph at one environment: images (sides, memory), buffers (bytes), pass
// groups/threads/repeat. `context` (e.g. "in test 'x' (64x64)") is added as a note when not empty.
Status validate_sizes(const GraphDesc& g, const SizeEnv& env, const std::string& context, const SourceLoc& context_loc);
// Every camera evaluates at `env` (with `test`'s overrides when given); passes name cameras
// that exist (validate_cameras.cpp).
Status validate_cameras(const GraphDesc& g, const SizeEnv& env, const TestDesc* test);

} // namespace pl::graph
