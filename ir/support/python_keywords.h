// Python 3's keywords, listed once for every part of smachac that writes or reads Python
// (soft keywords such as `match` and `case` are valid names, so they are not listed).
#pragma once

#include <algorithm>
#include <iterator>
#include <string_view>

namespace smachac {

inline constexpr std::string_view kPythonKeywords[] = {
    "False", "None",     "True",  "and",    "as",   "assert", "async",  "await",    "break",
    "class", "continue", "def",   "del",    "elif", "else",   "except", "finally",  "for",
    "from",  "global",   "if",    "import", "in",   "is",     "lambda", "nonlocal", "not",
    "or",    "pass",     "raise", "return", "try",  "while",  "with",   "yield"};

inline bool isPythonKeyword(std::string_view text) {
  return std::find(std::begin(kPythonKeywords), std::end(kPythonKeywords), text) !=
         std::end(kPythonKeywords);
}

}  // namespace smachac
