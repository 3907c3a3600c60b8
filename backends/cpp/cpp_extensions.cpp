// C++ literals for the C++ templates.
#include "backends/cpp/cpp_extensions.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <limits>

#include "backends/tmpl/values/value_print.h"

namespace smachac::backends::cpp {
namespace {

void expectNoArguments(const tmpl::CallArgs& args, const char* what) {
  if (args.size() != 0) tmpl::fail(std::string("`") + what + "` takes no arguments");
}

void appendEscaped(std::string& out, unsigned char c) {
  switch (c) {
    case '"':
      out += "\\\"";
      return;
    case '\\':
      out += "\\\\";
      return;
    case '\n':
      out += "\\n";
      return;
    case '\t':
      out += "\\t";
      return;
    case '\r':
      out += "\\r";
      return;
    default:
      break;
  }
  if (c < 0x20 || c >= 0x7f) {
    char octal[5];
    std::snprintf(octal, sizeof octal, "\\%03o", static_cast<unsigned>(c));
    out += octal;
    return;
  }
  out += static_cast<char>(c);
}

std::string intExpression(int64_t i) {
  if (i == std::numeric_limits<int64_t>::min()) return "int64_t{-9223372036854775807 - 1}";
  return "int64_t{" + std::to_string(i) + "}";
}

std::string doubleExpression(double d) {
  if (std::isnan(d)) return "std::numeric_limits<double>::quiet_NaN()";
  if (std::isinf(d)) {
    return d > 0 ? "std::numeric_limits<double>::infinity()"
                 : "-std::numeric_limits<double>::infinity()";
  }
  char text[40];
  for (int precision = 1; precision <= 17; ++precision) {  // the shortest text that round-trips
    std::snprintf(text, sizeof text, "%.*g", precision, d);
    if (std::strtod(text, nullptr) == d) break;
  }
  std::string out = text;
  if (out.find_first_of(".en") == std::string::npos) out += ".0";
  return "double{" + out + "}";
}

std::string stringExpression(const std::string& s) {
  if (s.find('\0') != std::string::npos) {
    return "std::string(" + cppStringLiteral(s) + ", " + std::to_string(s.size()) + ")";
  }
  return "std::string(" + cppStringLiteral(s) + ")";
}

bool isBacktickCode(const std::string& s) {
  return s.size() > 2 && s.front() == '`' && s.back() == '`';
}

std::string listExpression(const std::vector<tmpl::Value>& items, const IsForcedString& forced) {
  std::string out = "rt::List{";
  for (size_t i = 0; i < items.size(); ++i) {
    if (i != 0) out += ", ";
    out += "rt::Value(" + cppValueExpression(items[i], forced) + ")";
  }
  return out + "}";
}

std::string mapExpression(const tmpl::DictObject& dict, const IsForcedString& forced) {
  std::string out = "rt::Map{";
  bool first = true;
  for (const auto& [key, value] : dict.entries()) {
    if (!first) out += ", ";
    first = false;
    std::string key_text = key.isString() ? key.s() : tmpl::str(key);
    out += "{" + cppStringLiteral(key_text) + ", rt::Value(" + cppValueExpression(value, forced) +
           ")}";
  }
  return out + "}";
}

}  // namespace

std::string cppStringLiteral(std::string_view text) {
  std::string out = "\"";
  char previous = 0;
  for (char c : text) {
    if (c == '?' && previous == '?') {
      out += "\\?";  // no trigraph, whatever the compiler's mode
    } else {
      appendEscaped(out, static_cast<unsigned char>(c));
    }
    previous = c;
  }
  return out + "\"";
}

std::string cppValueExpression(const tmpl::Value& value) {
  return cppValueExpression(value, [](const tmpl::Value&) { return false; });
}

std::string cppUserdataArgument(const tmpl::Value& value, const IsForcedString& forced) {
  bool code = value.isString() && isBacktickCode(value.s()) && !forced(value);
  if (value.isString() && !code && value.s().find('\0') == std::string::npos) {
    return cppStringLiteral(value.s());
  }
  return cppValueExpression(value, forced);
}

std::string cppCommentText(std::string_view text) {
  std::string out;
  for (char c : text) {
    auto byte = static_cast<unsigned char>(c);
    if (c == '\\') {
      out += "\\134";  // never a backslash at the end of the line: that would splice lines
    } else if (byte < 0x20 || byte == 0x7f) {
      appendEscaped(out, byte);
    } else {
      out += c;
    }
  }
  return out;
}

std::string cppValueExpression(const tmpl::Value& value, const IsForcedString& forced) {
  if (value.isNone()) return "nullptr";
  if (value.isBool()) return value.b() ? "true" : "false";
  if (value.isInt()) return intExpression(value.i());
  if (value.isFloat()) return doubleExpression(value.f());
  if (value.isString() && isBacktickCode(value.s()) && !forced(value)) {
    return value.s().substr(1, value.s().size() - 2);
  }
  if (value.isString()) return stringExpression(value.s());
  if (value.isListOrTuple()) return listExpression(value.list().items(), forced);
  if (value.isDict()) return mapExpression(value.dict(), forced);
  if (value.isUndefined()) tmpl::fail(value.undefinedMessage());
  return stringExpression(tmpl::str(value));
}

void registerCppExtensions(tmpl::Environment& env, const generator::ValueConverter& converter,
                           bool include_comments) {
  env.addFilter("cppstr", [](const tmpl::Value& input, const tmpl::CallArgs& args) {
    expectNoArguments(args, "cppstr");
    if (input.isUndefined()) tmpl::fail(input.undefinedMessage());
    return tmpl::Value::string(cppStringLiteral(input.isString() ? input.s() : tmpl::str(input)));
  });
  env.addFilter("cppvalue", [&converter](const tmpl::Value& input, const tmpl::CallArgs& args) {
    expectNoArguments(args, "cppvalue");
    auto forced = [&converter](const tmpl::Value& v) { return converter.isForcedString(v); };
    return tmpl::Value::string(cppValueExpression(input, forced));
  });
  env.addFilter("cppuserdata", [&converter](const tmpl::Value& input, const tmpl::CallArgs& args) {
    expectNoArguments(args, "cppuserdata");
    auto forced = [&converter](const tmpl::Value& v) { return converter.isForcedString(v); };
    return tmpl::Value::string(cppUserdataArgument(input, forced));
  });
  env.addFilter("cppcomment", [](const tmpl::Value& input, const tmpl::CallArgs& args) {
    expectNoArguments(args, "cppcomment");
    if (input.isUndefined()) tmpl::fail(input.undefinedMessage());
    return tmpl::Value::string(cppCommentText(input.isString() ? input.s() : tmpl::str(input)));
  });
  env.addTest("forced_string", [&converter](const tmpl::Value& input, const tmpl::CallArgs& args) {
    expectNoArguments(args, "forced_string");
    return converter.isForcedString(input);
  });
  env.addGlobal("include_comments", tmpl::Value::boolean(include_comments));
}

}  // namespace smachac::backends::cpp
