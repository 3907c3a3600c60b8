// Python str()/repr() of values.
#include "ir/python_text.h"

#include <fmt/core.h>

#include "ir/support/python_float.h"
#include "ir/support/python_text.h"

namespace smachac::ir {

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
