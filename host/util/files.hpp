// Reading user files safely: only regular files (a FIFO blocks forever, /dev/zero never ends, a
// directory reads as nothing), only up to a size cap (checked before reading, so a huge file is
// an error, not an out-of-memory abort), and no std::filesystem call that can throw (symlink
// loops, names longer than NAME_MAX): every one takes an error_code.
#pragma once

#include "util/error.hpp"

#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace pl {

// Caps, generous for their kind: a preset.toml or shader is text typed by a person.
inline constexpr std::uintmax_t max_text_bytes = 16u << 20;    // 16 MiB
inline constexpr std::uintmax_t max_asset_bytes = 2048ull << 20;  // 2 GiB: images, meshes

// The size of `file` if it is a regular file (links followed) of at most `max_bytes`; else an
// error naming `what` ("preset", "shader", "image", "mesh") and why (missing, not a regular
// file, too large).
Result<std::uintmax_t> check_regular_file(const std::filesystem::path& file, std::uintmax_t max_bytes, const std::string& what);
// The whole file, after check_regular_file (never more than the size it checked).
Result<std::string> read_file_capped(const std::filesystem::path& file, std::uintmax_t max_bytes, const std::string& what);

// Regular files under `dir` (links to files count; links to folders are not followed, so a
// link loop cannot recurse), never throwing: unreadable folders and entries whose status fails
// (a link loop, a name too long) are skipped. At most `max_entries` entries are visited
// (`*truncated` says whether there were more): `--exercise /` must not walk the whole disk.
std::vector<std::filesystem::path> files_under(const std::filesystem::path& dir, size_t max_entries = 100000,
                                               bool* truncated = nullptr);

} // namespace pl
