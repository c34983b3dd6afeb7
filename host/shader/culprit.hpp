// Where in its source line a glslang message points: glslang gives a line but no column, so the
// column is found from what the message names.
#pragma once

#include <string>

namespace pl::shader {

// 1-based column of the message's culprit in `source` (the line glslang named), 0 if unknown:
// the first quoted token of the message when the line contains it; for a syntax error, the
// token the parser did not expect ("unexpected SEMICOLON" -> the first ';', FLOATCONSTANT ->
// the first number, IDENTIFIER -> the first name that is not a keyword, RETURN -> `return`).
int culprit_column(const std::string& msg, const std::string& source);

} // namespace pl::shader
