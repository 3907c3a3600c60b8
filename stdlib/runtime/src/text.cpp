// Internal text helpers: backticked names, quoting with escapes, key lookup.
#include "text.h"

#include <cstdio>

namespace smachac::runtime {

std::string backticked(std::string_view name) { return "`" + std::string(name) + "`"; }

void appendQuoted(std::string& out, std::string_view text, char quote, Escape style) {
  out += quote;
  for (char c : text) {
    switch (c) {
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\r':
        out += "\\r";
        break;
      case '\t':
        out += "\\t";
        break;
      default:
        if (c == quote) {
          out += '\\';
          out += c;
        } else if (static_cast<unsigned char>(c) < 0x20) {
          char escape[8];
          std::snprintf(escape, sizeof escape, style == Escape::Json ? "\\u%04x" : "\\x%02x",
                        static_cast<unsigned>(c));
          out += escape;
        } else {
          out += c;
        }
    }
  }
  out += quote;
}

int indexIn(const Keys& keys, std::string_view key) {
  for (std::size_t i = 0; i < keys.size(); ++i) {
    if (keys[i] == key) return static_cast<int>(i);
  }
  return -1;
}

}  // namespace smachac::runtime
