// Source text as it arrives from other tools: byte-order marks, CRLF line ends, a `#version`
// for another dialect, identifiers that GLSL 4.50 for Vulkan reserves but GLSL ES 3.00 does not.
// Every rewrite keeps the line count, so errors point at the user's lines.
#pragma once

#include "util/error.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace pl::import {

// The bytes of a file (a located error when it cannot be read).
Result<std::string> read_text_file(const std::filesystem::path& p);
// BOM dropped, CRLF and lone CR turned into LF.
std::string clean_text(std::string s);
// clean_text, then `#version` lines blanked and words reserved by Vulkan GLSL 4.50 renamed
// (`sampler` -> `sampler_`, `buffer`, `shared`, `precise`, `texture2D` used as a name ...).
std::string glsl_es_to_450(std::string s);
// Replaces whole-word identifier `from` by `to` outside comments (old-GLSL rewriting).
std::string replace_word(const std::string& s, const std::string& from, const std::string& to);
// The 1-based line and column of byte `offset` in `s`.
std::pair<int, int> line_col(const std::string& s, size_t offset);
// TOML basic string with quotes and escapes.
std::string toml_quote(const std::string& s);

} // namespace pl::import
