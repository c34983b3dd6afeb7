// Host-side include expansion for GLSL (see include.cpp).
#pragma once

#include "util/error.hpp"

#include <filesystem>
#include <string>
#include <vector>

namespace pl::shader {

struct Expanded {
    std::string text;                         // ready for glslang, with #line directives
    std::vector<std::filesystem::path> files;  // every file read, canonical
};

// `file` is the shader on disk (empty for generated sources), `text` its contents, `shown` the
// name errors use; `injected` goes after #version without shifting user line numbers.
Result<Expanded> expand_source(const std::filesystem::path& file, const std::string& text, const std::string& shown,
                               const std::string& injected, const std::vector<std::filesystem::path>& include_dirs);

// Reads a text file, stripping a UTF-8 BOM and CR of CRLF line ends.
Result<std::string> read_text(const std::filesystem::path& file);

// A path as shown in messages: relative to the working directory when possible.
std::string display_path(const std::filesystem::path& p);

// `name` as it can stand inside #line "..." (and glslang's messages): a quote, backslash or
// control character (a folder name with a newline) is replaced by '?', since it would end the
// directive and put the error inside the passlab preamble.
std::string line_name(const std::string& name);

} // namespace pl::shader
