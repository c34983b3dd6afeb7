// Bounded, linear scanners for the few shapes of text the host recognises: preprocessor lines
// in GLSL (#include, #version, #pragma once), glslang's log lines, decimal numbers. They replace
// std::regex, whose libstdc++ implementation recurses once per character matched and overflowed
// the stack (SIGSEGV, nothing printed) on a shader line of ~40,000 characters; and std::stoi,
// which throws on a number that does not fit.
#pragma once

#include <cstddef>
#include <optional>
#include <string>
#include <string_view>

namespace pl::scan {

bool is_blank(char c);       // space, tab, \v, \f, \r
bool is_word_char(char c);   // [A-Za-z0-9_]
size_t skip_blanks(std::string_view s, size_t pos = 0);

// `  #  word rest` -> "word" (the directive name) and, in *rest, what follows it; nullopt if
// the line is not a preprocessor directive.
std::optional<std::string_view> directive(std::string_view line, std::string_view* rest = nullptr);
// `#include "name"` or `#include <name>` (anything may follow): the name.
std::optional<std::string> include_name(std::string_view line);
bool is_pragma_once(std::string_view line);
bool is_version(std::string_view line);

// First occurrence of `word` in `s` as a whole word (not inside a longer identifier); npos if none.
size_t find_word(std::string_view s, std::string_view word);

// All of `digits` as a decimal number no greater than `max`; nullopt if empty, not all digits,
// or too large (never throws, never wraps).
std::optional<unsigned long long> parse_decimal(std::string_view digits, unsigned long long max);
// The same for an optionally signed int ("-12"), within [lo, hi].
std::optional<long long> parse_integer(std::string_view text, long long lo, long long hi);

} // namespace pl::scan
