// Python str()/repr() of values.
#include "ir/python_text.h"

#include <fmt/core.h>

#include "ir/support/python_float.h"

namespace smachac::ir {

std::string pythonStringRepr(std::string_view text) {
  bool has_single = text.find('\'') != std::string_view::npos;
  bool has_double = text.find('"') != std::string_view::npos;
  char quote = has_single && !has_double ? '"' : '\'';
  std::string out(1, quote);
  for (char ch : text) {
    unsigned char c = static_cast<unsigned char>(ch);
    if (ch == quote || ch == '\\') {
      out += '\\';
      out += ch;
    } else if (ch == '\n') {
      out += "\\n";
    } else if (ch == '\r') {
      out += "\\r";
    } else if (ch == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      out += fmt::format("\\x{:02x}", c);
    } else {
      out += ch;
    }
  }
  return out + quote;
}

std::string pythonRepr(const Value& value) {
  switch (value.kind()) {
    case ValueKind::String:
      return pythonStringRepr(value.asString());
    case ValueKind::Expression:
      return pythonStringRepr("`" + value.asExpression().code + "`");
    case ValueKind::List: {
      std::string out = "[";
      for (const Value& item : value.asList()) {
        if (out.size() > 1) out += ", ";
        out += pythonRepr(item);
      }
      return out + "]";
    }
    case ValueKind::Map: {
      std::string out = "{";
      for (const MapEntry& entry : value.asMap()) {
        if (out.size() > 1) out += ", ";
        out += pythonStringRepr(entry.key) + ": " + pythonRepr(entry.value);
      }
      return out + "}";
    }
    default:
      return pythonStr(value);
  }
}

std::string pythonStr(const Value& value) {
  switch (value.kind()) {
    case ValueKind::Null:
      return "None";
    case ValueKind::Bool:
      return value.asBool() ? "True" : "False";
    case ValueKind::Int:
      return std::to_string(value.asInt());
    case ValueKind::Float:
      return pythonFloatRepr(value.asFloat());
    case ValueKind::String:
      return value.asString();
    case ValueKind::Expression:
      return "`" + value.asExpression().code + "`";
    case ValueKind::List:
    case ValueKind::Map:
      return pythonRepr(value);
  }
  return "None";
}

}  // namespace smachac::ir
