// Python literals, SMACHA's bare values, comment text and identifier parts.
#include "backends/smach/python_code.h"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "backends/tmpl/values/py_number.h"
#include "backends/tmpl/values/value_print.h"
#include "ir/support/python_keywords.h"
#include "ir/support/python_text.h"

namespace smachac::backends::smach {
namespace {

bool isDigit(char c) { return c >= '0' && c <= '9'; }

/// [A-Za-z_][A-Za-z0-9_]*, not a keyword.
bool isPlainName(std::string_view text) {
  if (text.empty() || isDigit(text[0])) return false;
  if (!std::all_of(text.begin(), text.end(), isIdentifierChar)) return false;
  return !isPythonKeyword(text);
}

/// Two or more plain names joined by dots (`geometry_msgs.msg.Point`, `data.csv`).
bool isDottedName(std::string_view text) {
  size_t parts = 0;
  size_t start = 0;
  while (true) {
    size_t dot = text.find('.', start);
    if (!isPlainName(text.substr(start, dot == std::string_view::npos ? dot : dot - start))) {
      return false;
    }
    ++parts;
    if (dot == std::string_view::npos) return parts >= 2;
    start = dot + 1;
  }
}

size_t skipDigits(std::string_view text, size_t at) {
  while (at < text.size() && isDigit(text[at])) ++at;
  return at;
}

/// [+-]?(0|[1-9][0-9]*)(\.[0-9]+)?([eE][+-]?[0-9]+)?: a Python number literal as written.
bool isNumberLiteral(std::string_view text) {
  size_t at = !text.empty() && (text[0] == '+' || text[0] == '-') ? 1 : 0;
  size_t end = skipDigits(text, at);
  if (end == at || (text[at] == '0' && end - at > 1)) return false;
  if (end < text.size() && text[end] == '.') {
    size_t fraction = skipDigits(text, end + 1);
    if (fraction == end + 1) return false;
    end = fraction;
  }
  if (end < text.size() && (text[end] == 'e' || text[end] == 'E')) {
    size_t sign = end + 1 < text.size() && (text[end + 1] == '+' || text[end + 1] == '-');
    size_t exponent = skipDigits(text, end + 1 + sign);
    if (exponent == end + 1 + sign) return false;
    end = exponent;
  }
  return end == text.size();
}

/// Where the bracket opened at `open` closes, skipping string literals; npos if it does not.
size_t matchingBracket(std::string_view text, size_t open) {
  int depth = 0;
  for (size_t at = open; at < text.size(); ++at) {
    char c = text[at];
    if (c == '\'' || c == '"') {
      for (++at; at < text.size() && text[at] != c; ++at) {
        if (text[at] == '\\') ++at;
      }
      if (at >= text.size()) return std::string_view::npos;
    } else if (c == '(' || c == '[' || c == '{') {
      ++depth;
    } else if (c == ')' || c == ']' || c == '}') {
      if (--depth == 0) return at;
    }
  }
  return std::string_view::npos;
}

/// SMACHA's call shape (`.+\(.*\)$`), narrowed to one call: a name or dotted name, then
/// arguments whose brackets close at the end of the text (so `f(); g()` is no call), on one
/// line without control characters.
bool isCallShaped(std::string_view text) {
  bool control = std::any_of(text.begin(), text.end(), [](char c) {
    return static_cast<unsigned char>(c) < 0x20 || c == 0x7f;
  });
  if (control || text.size() < 3 || text.back() != ')') return false;
  size_t open = text.find('(');
  if (open == std::string_view::npos) return false;
  std::string_view callee = text.substr(0, open);
  if (!isPlainName(callee) && !isDottedName(callee)) return false;
  return matchingBracket(text, open) == text.size() - 1;
}

std::string floatLiteral(double d) {
  if (std::isnan(d)) return "float('nan')";
  if (std::isinf(d)) return d > 0 ? "float('inf')" : "-float('inf')";
  return tmpl::repr(tmpl::Value::real(d));
}

}  // namespace

std::string pythonLiteral(const tmpl::Value& value) {
  if (value.isFloat()) return floatLiteral(value.f());
  if (value.isListOrTuple()) {
    std::vector<std::string> items;
    for (const tmpl::Value& item : value.list().items()) items.push_back(pythonLiteral(item));
    if (value.isTuple()) {
      return "(" + fmt::format("{}", fmt::join(items, ", ")) + (items.size() == 1 ? ",)" : ")");
    }
    return "[" + fmt::format("{}", fmt::join(items, ", ")) + "]";
  }
  if (value.isDict()) {
    std::vector<std::string> entries;
    for (const auto& [key, item] : value.dict().entries()) {
      entries.push_back(pythonLiteral(key) + ": " + pythonLiteral(item));
    }
    return "{" + fmt::format("{}", fmt::join(entries, ", ")) + "}";
  }
  return tmpl::repr(value);
}

std::string pythonCode(const tmpl::Value& value) {
  if (!value.isString()) return pythonLiteral(value);
  const std::string& text = value.s();
  if (isNumberLiteral(text) || isDottedName(text)) return text;
  double ignored;
  bool number_like = tmpl::parsePythonFloat(text, ignored);
  if (!number_like && isCallShaped(text)) return text;
  return tmpl::repr(value);
}

std::string pythonComment(std::string_view text) {
  std::string out;
  appendPythonEscapes(out, text);
  return out;
}

std::string identifierPart(std::string_view text) {
  std::string out;
  for (char c : text) {
    if (isIdentifierChar(c)) {
      out += c;
    } else {
      out += fmt::format("_x{:02x}", static_cast<unsigned char>(c));
    }
  }
  return out;
}

}  // namespace smachac::backends::smach
