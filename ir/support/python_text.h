// Python's text rules, written once for every part of smachac that writes or reads Python:
// the repr() of a str (quotes chosen as Python chooses them; backslash, the quote, \t \n \r
// and every character Python's str.isprintable() refuses escaped as \xHH, \uHHHH or
// \UHHHHHHHH), the same escapes without quotes for text that must stay on one line, and the
// characters of an ASCII identifier. Floats: python_float.h; keywords: python_keywords.h.
#pragma once

#include <string>
#include <string_view>

namespace smachac {

/// Python's repr() of the str `text` (UTF-8; invalid bytes as surrogate escapes).
std::string pythonStringRepr(std::string_view text);
void appendPythonStringRepr(std::string& out, std::string_view text);

/// The escapes of repr() for the characters Python would not print (\t \n \r included), the
/// rest as it is: text that stays on one line, e.g. of a `#` comment.
void appendPythonEscapes(std::string& out, std::string_view text);

/// [A-Za-z0-9_].
bool isIdentifierChar(char c);

}  // namespace smachac
