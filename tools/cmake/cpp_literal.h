// Shared by the build's source generators (embed_gen.cpp, meta_table_gen.cpp): bytes written
// as a C++ string literal, exactly. Printable ASCII stays as it is (but `"`, `\` and `?`, which
// could end the literal or form a trigraph); every other byte becomes a three-digit octal
// escape, which never runs into the character after it.
#pragma once

#include <cstdio>
#include <string>
#include <string_view>

namespace smachac::build {

/// `text` as a C++ string literal; with `split_lines`, as adjacent literals, one per line of
/// `text`, so that the generated source stays readable.
inline std::string cppStringLiteral(std::string_view text, bool split_lines = false) {
  std::string out = "\"";
  for (unsigned char c : text) {
    if (c >= 0x20 && c < 0x7f && c != '"' && c != '\\' && c != '?') {
      out += static_cast<char>(c);
      continue;
    }
    char escaped[8];
    std::snprintf(escaped, sizeof escaped, "\\%03o", c);
    out += escaped;
    if (split_lines && c == '\n') out += "\"\n    \"";
  }
  return out + "\"";
}

}  // namespace smachac::build
