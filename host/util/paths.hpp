// Path relations the host needs in more than one place (include shadowing, `passlab new`).
#pragma once

#include <filesystem>
#include <optional>

namespace pl {

// `p` relative to `dir` when `p` lies inside `dir` (both made canonical first, so links and
// "..": never match by spelling alone); nullopt otherwise, and for `dir` itself.
std::optional<std::filesystem::path> path_within(const std::filesystem::path& p, const std::filesystem::path& dir);

// weakly_canonical without exceptions: on failure (a symlink loop, a name longer than NAME_MAX)
// the lexically normal absolute path, so identity checks still work and nothing aborts.
std::filesystem::path canonical_or_normal(const std::filesystem::path& p);

// A GLSL source by its extension: the stage suffixes, .glsl includes and ISF's .fs/.vs. Used
// where a shader given as a preset gets a pointed message, and by `mutate` to pick the files
// it may change.
bool is_shader_file(const std::filesystem::path& p);

} // namespace pl
