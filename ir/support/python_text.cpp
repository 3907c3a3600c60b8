// Python's str repr() and escapes.
#include "ir/support/python_text.h"

#include "ir/support/unicode.h"

namespace smachac {
namespace {

void appendHex(std::string& out, char prefix, uint32_t code, int digits) {
  static constexpr char kHex[] = "0123456789abcdef";
  out += '\\';
  out += prefix;
  for (int shift = (digits - 1) * 4; shift >= 0; shift -= 4) out += kHex[(code >> shift) & 15];
}

/// One character as repr() writes it between `quote`s ('\0': no quote, backslash kept).
void appendEscaped(std::string& out, char32_t cp, char quote) {
  if (quote != '\0' && (cp == static_cast<char32_t>(quote) || cp == '\\')) {
    out += '\\';
    out += static_cast<char>(cp);
  } else if (cp == '\t') {
    out += "\\t";
  } else if (cp == '\n') {
    out += "\\n";
  } else if (cp == '\r') {
    out += "\\r";
  } else if (unicode::isPrintable(cp)) {
    unicode::encode(out, cp);
  } else if (cp <= 0xFF) {
    appendHex(out, 'x', cp, 2);
  } else if (cp <= 0xFFFF) {
    appendHex(out, 'u', cp, 4);
  } else {
    appendHex(out, 'U', cp, 8);
  }
}

void appendEscapedText(std::string& out, std::string_view text, char quote) {
  for (size_t pos = 0; pos < text.size();) {
    unsigned char c = static_cast<unsigned char>(text[pos]);
    if (c >= 0x20 && c < 0x7F && c != '\\' && c != static_cast<unsigned char>(quote)) {
      out += static_cast<char>(c);
      ++pos;
      continue;
    }
    appendEscaped(out, unicode::decode(text, pos), quote);
  }
}

}  // namespace

void appendPythonStringRepr(std::string& out, std::string_view text) {
  bool has_single = text.find('\'') != std::string_view::npos;
  bool has_double = text.find('"') != std::string_view::npos;
  char quote = has_single && !has_double ? '"' : '\'';
  out += quote;
  appendEscapedText(out, text, quote);
  out += quote;
}

std::string pythonStringRepr(std::string_view text) {
  std::string out;
  appendPythonStringRepr(out, text);
  return out;
}

void appendPythonEscapes(std::string& out, std::string_view text) {
  appendEscapedText(out, text, '\0');
}

bool isIdentifierChar(char c) {
  return (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') || c == '_';
}

}  // namespace smachac
