// Writing values in flow style.
#include "refactor/flow_text.h"

#include <fmt/core.h>

#include <cmath>

#include "frontend/scalar.h"
#include "ir/python_text.h"
#include "refactor/yaml_spans.h"

namespace smachac::refactor {
namespace {

constexpr std::string_view kIndicators = "-?:,[]{}#&*!|>'\"%@`";

bool needsDoubleQuotes(std::string_view s) {
  for (unsigned char c : s) {
    if (c < 0x20 || c == 0x7f) return true;
  }
  return false;
}

bool plainSafe(std::string_view s) {
  if (s.empty() || kIndicators.find(s.front()) != std::string_view::npos) return false;
  if (s.front() == ' ' || s.back() == ' ' || s.back() == ':') return false;
  if (s.find(": ") != std::string_view::npos || s.find(" #") != std::string_view::npos) {
    return false;
  }
  if (s.find_first_of(",[]{}") != std::string_view::npos || needsDoubleQuotes(s)) return false;
  ir::Value v = frontend::resolveScalar(s, frontend::ScalarStyle::Plain, "", {}).value;
  return v.isString() && v.asString() == s;
}

std::string doubleQuoted(std::string_view s) {
  std::string out = "\"";
  for (unsigned char c : s) {
    if (c == '"' || c == '\\') {
      out += '\\';
      out += static_cast<char>(c);
    } else if (c == '\n') {
      out += "\\n";
    } else if (c == '\t') {
      out += "\\t";
    } else if (c < 0x20 || c == 0x7f) {
      out += fmt::format("\\x{:02x}", c);
    } else {
      out += static_cast<char>(c);
    }
  }
  return out + "\"";
}

std::string singleQuoted(std::string_view s) {
  std::string out = "'";
  for (char c : s) {
    out += c;
    if (c == '\'') out += '\'';
  }
  return out + "'";
}

std::string quoted(std::string_view s) {
  return needsDoubleQuotes(s) ? doubleQuoted(s) : singleQuoted(s);
}

std::string joined(const std::vector<std::string>& items) {
  std::string out;
  for (const std::string& item : items) out += (out.empty() ? "" : ", ") + item;
  return out;
}

std::string floatText(double d) {
  if (std::isnan(d)) return ".nan";
  if (std::isinf(d)) return d > 0 ? ".inf" : "-.inf";
  return ir::pythonRepr(ir::Value::real(d));
}

}  // namespace

std::string flowScalar(std::string_view text) {
  return plainSafe(text) ? std::string(text) : quoted(text);
}

std::string flowValue(const ir::Value& value) {
  switch (value.kind()) {
    case ir::ValueKind::Null:
      return "null";
    case ir::ValueKind::Bool:
      return value.asBool() ? "true" : "false";
    case ir::ValueKind::Int:
      return std::to_string(value.asInt());
    case ir::ValueKind::Float:
      return floatText(value.asFloat());
    case ir::ValueKind::String:
      return value.forced_string ? "!str " + quoted(value.asString())
                                 : flowScalar(value.asString());
    case ir::ValueKind::Expression:
      if (value.asPortable()) return "!expr " + quoted(value.asExpression().code);
      return quoted("`" + value.asExpression().code + "`");
    case ir::ValueKind::List: {
      std::vector<std::string> items;
      for (const ir::Value& item : value.asList()) items.push_back(flowValue(item));
      return "[" + joined(items) + "]";
    }
    case ir::ValueKind::Map: {
      std::vector<std::pair<std::string, std::string>> entries;
      for (const ir::MapEntry& e : value.asMap()) entries.emplace_back(e.key, flowValue(e.value));
      return flowMap(entries);
    }
  }
  return "null";
}

std::string flowNameList(const std::vector<std::string>& names) {
  std::vector<std::string> items;
  for (const std::string& name : names) items.push_back(flowScalar(name));
  return "[" + joined(items) + "]";
}

std::string flowMap(const std::vector<std::pair<std::string, std::string>>& entries) {
  std::vector<std::string> items;
  for (const auto& [key, value] : entries) items.push_back(flowScalar(key) + ": " + value);
  return "{" + joined(items) + "}";
}

std::string inlineText(const SourceText& text, const EditList& edits, const ir::Value& value,
                       Span span) {
  bool one_line = span.begin < span.end && text.lineOf(span.begin) == text.lineOf(span.end - 1);
  char first = text.at(nodeStart(text, value));
  bool block = ((value.isMap() || value.isList()) && !isFlowCollection(text, value)) ||
               (!value.isMap() && !value.isList() && (first == '|' || first == '>'));
  return one_line && !block ? edits.render(text.text(), span) : flowValue(value);
}

}  // namespace smachac::refactor
