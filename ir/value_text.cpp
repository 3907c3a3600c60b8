// Value text formatting for the IR printer.
#include "ir/value_text.h"

#include <fmt/core.h>

#include "ir/support/python_float.h"

namespace smachac::ir {

std::string quoteString(std::string_view text) {
  std::string out = "\"";
  for (char ch : text) {
    unsigned char c = static_cast<unsigned char>(ch);
    switch (ch) {
      case '"':
        out += "\\\"";
        break;
      case '\\':
        out += "\\\\";
        break;
      case '\n':
        out += "\\n";
        break;
      case '\t':
        out += "\\t";
        break;
      case '\r':
        out += "\\r";
        break;
      default:
        if (c < 0x20 || c == 0x7f) {
          out += fmt::format("\\x{:02x}", c);
        } else {
          out += ch;
        }
    }
  }
  return out + "\"";
}

std::string formatKey(std::string_view text) {
  bool plain = !text.empty();
  for (char c : text) {
    bool ok = (c >= 'a' && c <= 'z') || (c >= 'A' && c <= 'Z') || (c >= '0' && c <= '9') ||
              c == '_' || c == '.' || c == '-' || c == '/';
    plain = plain && ok;
  }
  return plain ? std::string(text) : quoteString(text);
}

std::string formatValue(const Value& value) {
  switch (value.kind()) {
    case ValueKind::Null:
      return "null";
    case ValueKind::Bool:
      return value.asBool() ? "true" : "false";
    case ValueKind::Int:
      return std::to_string(value.asInt());
    case ValueKind::Float:
      return pythonFloatRepr(value.asFloat());
    case ValueKind::String:
      return (value.forced_string ? "!str " : "") + quoteString(value.asString());
    case ValueKind::Expression:
      if (value.asPortable()) return "!expr " + quoteString(value.asExpression().code);
      return "`" + value.asExpression().code + "`";
    case ValueKind::List: {
      std::string out = "[";
      for (const Value& item : value.asList()) {
        if (out.size() > 1) out += ", ";
        out += formatValue(item);
      }
      return out + "]";
    }
    case ValueKind::Map: {
      std::string out = "{";
      for (const MapEntry& entry : value.asMap()) {
        if (out.size() > 1) out += ", ";
        out += formatKey(entry.key) + ": " + formatValue(entry.value);
      }
      return out + "}";
    }
  }
  return "null";
}

}  // namespace smachac::ir
